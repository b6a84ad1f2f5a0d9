"""The plugin's probe: ``YADE_PREFIX=PREFIX yade -n -x probe_scene.py OUT.json``.

Steps the small box of ``scene.py`` with the plugin and on the PyRunner path
and writes {"ok", "why", ...} to OUT.json (yade_scripts.yadeplugin.probe
reads it; a crash leaves no file).
"""
import json
import sys

from yade_scripts.yadeplugin.scene import compare_paths

try:
    ok, why, details = compare_paths(O, globals())
except Exception as exc:          # noqa: BLE001 - any failure is a refusal, said in one line
    ok, why, details = False, f"{type(exc).__name__}: {exc}", {}
with open(sys.argv[1], "w") as fh:
    json.dump({"ok": ok, "why": why, **details}, fh)
print(f"probe: {'ok' if ok else 'refused'}: {why}", flush=True)
sys.exit(0)
