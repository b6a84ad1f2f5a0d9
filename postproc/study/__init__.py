"""The study layer of ``postproc``: what only the rebuild of the paper's
study needs, on top of the analysis library: the six claims and their
verdicts (:mod:`.claims`), the study report (:mod:`.report`), the
speed/error front (:mod:`.front`), dilatancy at the peak (:mod:`.dilatancy`)
and the branch-length investigation (:mod:`.branchlength`,
:mod:`.alinvestigation`); and the analyses behind the documentation's
further results (``postproc --help`` lists their subcommands): claim 6 by contact count
and criterion (:mod:`.counts`, :mod:`.claim6`), the size front
(:mod:`.sizefront`, :mod:`.sizestrain`, :mod:`.leaning`), LMGC90's count
(:mod:`.lmgc90`, :mod:`.commonplaneref`), contact types against the
stiffness and by chance (:mod:`.typeskappa`, :mod:`.randomtypes`), the
face-pair tilt (:mod:`.facepair`) and the time step's front
(:mod:`.timestepfront`)."""
