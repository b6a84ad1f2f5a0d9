"""A study's manifest.json: the runs of each sample, their dumps, analyses
and status, as the study (:mod:`yade_scripts.campaign.study`) writes it; read and
checked here for the report and the results."""
from __future__ import annotations

from ..errors import InputError, read_json


def read_manifest(path):
    """A study's manifest.json: {sample: [run dict]}, each run a dict whose
    "label" and "status" are text; InputError in one line naming the file
    when it is not JSON or not of that shape (:func:`postproc.errors.read_json`)."""
    runs = read_json(path, "study manifest")
    if not isinstance(runs, dict):
        raise InputError(f"{path}: not a study manifest (its top level is a {type(runs).__name__}, "
                         "not an object of samples)")
    for sample, rs in runs.items():
        if not isinstance(rs, list) or not all(isinstance(r, dict) for r in rs):
            raise InputError(f"{path}: not a study manifest (sample {sample!r} is not a list of runs)")
        for k, r in enumerate(rs):
            for key in ("label", "status"):
                if not isinstance(r.get(key), str):
                    raise InputError(f"{path}: not a study manifest (run {k + 1} of {sample!r} has no "
                                     f"text {key})")
            for key in ("dump", "analysis", "info"):
                if r.get(key) is not None and not isinstance(r[key], str):
                    raise InputError(f"{path}: not a study manifest (run {k + 1} of {sample!r}: "
                                     f"{key} is not a path)")
            if r.get("counts") is not None and not (isinstance(r["counts"], dict)
                                                    and all(isinstance(v, str) for v in r["counts"].values())):
                raise InputError(f"{path}: not a study manifest (run {k + 1} of {sample!r}: "
                                 "counts is not an object of paths)")
    return runs
