"""``python -m yade_scripts.yadeplugin build | status | prefix``.

build   build and probe the plugin for the installed YADE unless done (exit 0
        either way: a plugin that cannot be built leaves the PyRunner path)
status  one line: ready (and where), or why not; exit 0 ready, 1 not
prefix  print the YADE_PREFIX of the ready plugin; exit 1 (reason on stderr) if none
"""
import os
import sys

from . import build, status


def main(argv=None):
    """``python -m yade_scripts.yadeplugin build | status | prefix`` (the
    module docstring).

    Parameters
    ----------
    argv : list of str, optional
        The command line's arguments (default: ``sys.argv[1:]``; none:
        ``status``).

    Returns
    -------
    int
        The exit code: ``build`` 0 either way; ``status`` and ``prefix`` 0
        when the plugin is ready, else 1; 2 for another command.
    """
    argv = sys.argv[1:] if argv is None else argv
    cmd = argv[0] if argv else "status"
    if cmd == "build":
        st = build(quiet=False)
        print(f"yadeplugin: {'ready: ' + st['prefix'] if st['ok'] else 'not used, the scenes step on the PyRunner path: ' + st['why']}")
        if st["ok"]:
            root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
            print(f"yadeplugin: start YADE with it: YADE_PREFIX={st['prefix']} yade script.py\n"
                  f"yadeplugin: or let a script load it (no YADE_PREFIX): PYTHONPATH={root} yade script.py, the script "
                  "using yade_scripts.yadeplugin.contacts.PolyhedraContactEngine (examples/)")
        return 0
    if cmd in ("status", "prefix"):
        st = status()
        if cmd == "prefix" and st["ok"]:
            print(st["prefix"])
            return 0
        line = f"ready: {st['prefix']}" if st["ok"] else f"not ready: {st['why']}"
        print(f"yadeplugin: {line}", file=sys.stdout if cmd == "status" else sys.stderr)
        return 0 if st["ok"] else 1
    print(f"usage: python -m yade_scripts.yadeplugin build | status | prefix (got {cmd!r})", file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
