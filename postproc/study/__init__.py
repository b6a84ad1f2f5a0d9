"""The study layer of ``postproc``: what only the rebuild of the paper's
study needs, on top of the analysis library: the six claims and their
verdicts (:mod:`.claims`), the study report (:mod:`.report`), the
speed/error front (:mod:`.front`), dilatancy at the peak (:mod:`.dilatancy`)
and the branch-length investigation (:mod:`.branchlength`)."""
