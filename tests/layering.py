"""What the layering tests of ``postproc`` (tests/test_layers.py) and of
``yade_scripts`` (tests/test_yade_layers.py) share: finding an import loop."""


def import_loop(graph):
    """The first import loop of ``graph`` ({module: imported modules}) as the
    list of modules around it, the first repeated at the end; None without one.
    Imported names that are not keys of ``graph`` are not followed."""
    state = {}

    def visit(m, path):
        if state.get(m) == "open":
            return path[path.index(m):] + [m]
        if state.get(m) == "done":
            return None
        state[m] = "open"
        for d in sorted(graph.get(m, ())):
            if d in graph:
                loop = visit(d, path + [m])
                if loop:
                    return loop
        state[m] = "done"
        return None

    for m in sorted(graph):
        loop = visit(m, [])
        if loop:
            return loop
    return None
