"""The defaults the README and docs quote, held against the code: the
Makefile's variables and targets, the command make study runs, the presets,
the contact-type criteria and their options, the claims' thresholds, the
front's plans and the cost model's table. A default changed in the code
without its sentence (or the other way round) fails here."""
import math
import os
import re

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def text(path):
    with open(os.path.join(ROOT, path)) as fh:
        return fh.read()


def makefile_vars():
    """{NAME: default} of the Makefile's ``NAME ?= value`` lines."""
    return dict(re.findall(r"^(?:export )?([A-Z_]+) \?= (.*)$", text("Makefile"), re.M))


def makefile_recipe(target):
    """The recipe lines of a Makefile target, continuation lines joined."""
    lines = text("Makefile").split("\n")
    i = next(k for k, line in enumerate(lines) if re.match(rf"^{re.escape(target)}:", line))
    recipe = []
    for line in lines[i + 1:]:
        if not line.startswith("\t"):
            break
        recipe.append(line.strip())
    return " ".join(recipe).replace("\\ ", "")


def test_the_makefile_targets_the_readme_names_exist():
    targets = set(re.findall(r"^([a-z-]+):", text("Makefile"), re.M))
    named = set(re.findall(r"`?make ([a-z-]+)", text("README.md")))
    assert named and named <= targets, named - targets
    assert {"test", "study", "test-fast", "results", "docs", "front", "size-front"} <= targets


def test_what_make_study_runs_is_what_docs_study_quotes():
    v = makefile_vars()
    assert (v["PRESET"], v["STUDY"], v["ENSEMBLE"], v["JOBS"], v["JOB_THREADS"]) == \
        ("default", "runs/study", "3", "2", "1")
    recipe = makefile_recipe("study")
    assert "SHAPES ?=\n" in text("Makefile")     # no library of one's own by default: the $(if ...) adds nothing
    assert "COUNTS ?=\n" in text("Makefile")     # the study's default counts: the $(if ...) adds nothing
    assert "ARCHIVE ?=\n" in text("Makefile")    # no archive of analysed runs by default: the same
    assert "SET_ASIDE ?=\n" in text("Makefile") and "DRY_RUN ?=\n" in text("Makefile")   # off by default
    for part in ("$(if $(SHAPES),--library $(SHAPES))", "$(if $(COUNTS),--counts $(COUNTS))",
                 "$(if $(ARCHIVE),--archive $(ARCHIVE))", "$(if $(SET_ASIDE),--set-aside)",
                 "$(if $(DRY_RUN),--dry-run)"):
        recipe = recipe.replace(part, "")
    for name, value in v.items():
        recipe = recipe.replace(f"$({name})", value)
    cmd = re.search(r"\$\(PY\) -m (yade_scripts\.campaign\.study [^@]*)", recipe).group(1)   # then the comparison
    cmd = " ".join(cmd.split())
    assert f"python -m {cmd}\n" in text("docs/study.md")
    # the README quotes the default's seeds
    assert f"{v['ENSEMBLE']} seeds each" in text("README.md")


def test_the_study_command_defaults_are_what_docs_study_says():
    from yade_scripts.campaign.study import main  # noqa: F401  (importable)
    src = text("yade_scripts/campaign/study.py")
    assert re.search(r'"--ensemble", type=int, default=1\b', src)
    assert "runs one seed per sample unless given `--ensemble N`" in " ".join(text("docs/study.md").split())


def test_make_front_runs_the_front_commands_default_plan():
    from yade_scripts.campaign.sweeps import DEFAULT_PLAN, PLANS

    assert makefile_vars()["FRONT_PLAN"] == DEFAULT_PLAN == "default"
    front = text("docs/front.md")
    assert f"--plan {DEFAULT_PLAN} --out runs/front" in front
    for plan in PLANS:
        assert f"`{plan}`" in front, plan
    runs = sum(len(PLANS["default"][s]) for s in ("polyhedra", "spheres"))   # a line per seed and point
    assert f"{runs} runs" in front


PRESET_FACTS = {
    # preset: {sample: {parameter: value the docs state}}
    "default": {"polyhedra": {"n_particles": 1000, "kappa": 3000.0, "inertial_number": 5e-3, "safety": 0.45,
                              "compaction_friction": 0.5, "friction": 0.5, "placement": "grains",
                              "initial_fraction": 0.25, "compaction_inertial_number": 0.1, "final_strain": 0.3},
                "spheres": {"n_particles": 1000, "kappa": 3000.0, "inertial_number": 1e-3, "safety": 0.3,
                            "compaction_friction": 0.0, "friction": 0.5}},
    "small": {"polyhedra": {"n_particles": 200}, "spheres": {"n_particles": 200, "inertial_number": 1e-3}},
    "intermediate": {"polyhedra": {"n_particles": 5000, "kappa": 3000.0, "inertial_number": 5e-3},
                     "spheres": {"n_particles": 5000, "inertial_number": 1e-3}},
    "paper": {"polyhedra": {"n_particles": 36933, "kappa": 1e4, "inertial_number": 1e-3, "safety": 0.45,
                            "compaction_inertial_number": 1e-2},
              "spheres": {"n_particles": 19998, "compaction_friction": 0.0}},
    "soft": {"polyhedra": {"kappa": 300.0, "inertial_number": 2e-2, "placement": "spheres", "safety": 0.3}},
    "matched": {"polyhedra": {"compaction_friction": 0.58}},
    "loose": {"polyhedra": {"compaction_friction": 0.5}, "spheres": {"compaction_friction": 0.5}},
    "dense": {"polyhedra": {"compaction_friction": 0.0}, "spheres": {"compaction_friction": 0.0}},
    "tiny": {"polyhedra": {"n_particles": 20}, "spheres": {"n_particles": 40}},
}


@pytest.mark.parametrize("preset", sorted(PRESET_FACTS))
def test_the_presets_are_what_the_docs_say(preset):
    from yade_scripts.campaign.presets import resolve

    for sample, facts in PRESET_FACTS[preset].items():
        p = resolve(preset, sample)
        assert {k: p[k] for k in facts} == facts, (preset, sample)


def test_every_preset_is_documented():
    from yade_scripts.campaign.presets import PRESETS

    assert set(PRESETS) == set(PRESET_FACTS)
    scenes, doc = text("docs/scenes.md"), text("yade_scripts/campaign/presets.py")
    for name in PRESETS:
        assert f"`{name}`" in scenes, name
        assert f"``{name}``" in doc, name


def test_the_default_scene_is_the_default_presets_polyhedra():
    """triaxial.py's own block holds the parameter table's defaults, which
    are the default preset's S1 (docs/scenes.md)."""
    from yade_scripts.scene.parameters import PARAMETERS
    from yade_scripts.campaign.presets import resolve

    p = resolve("default", "polyhedra")
    assert {q.name: q.default for q in PARAMETERS if q.name in p} == {q.name: p[q.name] for q in PARAMETERS
                                                                      if q.name in p}
    assert re.search(r"^    safety=0\.45,", text("yade_scripts/scene/triaxial.py"), re.M)


def test_the_criteria_and_their_options():
    from postproc.classify import DEFAULT_METHOD, METHODS

    assert DEFAULT_METHOD == "points"
    words = {2: "Two", 3: "Three", 4: "Four", 5: "Five", 6: "Six", 7: "Seven"}
    assert text("postproc/classify.py").split("\n")[2].startswith(f"{words[len(METHODS)]} criteria")
    assert f"[--types {'|'.join(METHODS)}]" in text("docs/postproc.md")
    for m in METHODS:
        assert f"`{m}`" in text("docs/postproc.md"), m


def test_the_cli_defaults_are_the_usage_lines(capsys):
    from postproc.classify import METHODS
    from postproc.cli import main

    with pytest.raises(SystemExit):
        main(["analyze", "--help"])
    helptext = " ".join(capsys.readouterr().out.split())
    assert "{" + ",".join(METHODS) + "}" in helptext
    for default in ("(default z)", "(default 18)", "(default 0.1)", "(default 5)"):
        assert default in helptext, default
    usage = text("docs/postproc.md")
    for shown in ("[--axis z]", "[--bins 18]", "[--tolerance 0.1]", "[--threshold 0.1]", "[--theta 5]"):
        assert shown in usage, shown


def test_the_claims_thresholds_the_docs_quote():
    from postproc.study import claims
    from yade_scripts.runs.runstate import MAX_RESUMES

    study = " ".join(text("docs/study.md").split())
    assert f"|a_l| < {claims.NEGLIGIBLE:g}" in study
    assert f"within ±{claims.SFF_TOLERANCE:g}" in study
    assert f"≥ {claims.THROUGHOUT:.0%}".replace("%", " %") in study
    assert f"first {claims.EARLY:.0%}".replace("%", " %") in study
    assert f"±{claims.BAND_STABLE:g}" in study
    assert f"(up to {MAX_RESUMES} times)" in study


def test_the_cost_model_table_is_the_model():
    """docs/scenes.md's table of the cost model, row by row, against
    yade_scripts.launch.slurm.estimate on the presets (rounded as printed)."""
    from yade_scripts.campaign.presets import resolve
    from yade_scripts.launch.slurm import estimate

    scenes = text("docs/scenes.md")
    block = scenes[scenes.index("| preset, sample | grains |"):]
    rows = [r for r in block.split("\n")[2:] if r.startswith("|")]
    assert len(rows) == 6
    for row in rows:
        label, grains, steps, contacts, hours = [c.strip() for c in row.strip("|").split("|")]
        preset = label.split()[0]
        sample = "polyhedra" if label.split()[1] == "S1" else "spheres"
        p = resolve(preset, sample)
        e = estimate(p)
        assert int(grains.replace(" ", "")) == p["n_particles"], row
        assert float(steps) == float(f"{e['steps']:.2g}"), row
        assert float(contacts.replace(" ", "")) == pytest.approx(e["contacts"], rel=0.005), row
        decimals = len(hours.split(".")[1]) if "." in hours else 0
        assert abs(float(hours) - e["core_hours"]) <= 0.5 * 10 ** -decimals + 1e-12, row


def test_the_core_hours_the_docs_quote():
    from yade_scripts.campaign.presets import resolve
    from yade_scripts.launch.slurm import estimate

    def pair(preset):
        return sum(estimate(resolve(preset, s))["core_hours"] for s in ("polyhedra", "spheres"))

    scenes = " ".join(text("docs/scenes.md").split())
    assert f"about {pair('default'):.2f} core-hours per seed pair by the model" in scenes
    assert f"about {3 * pair('intermediate'):.1f} core-hours by the model" in scenes
    assert f"about {16 * pair('intermediate'):.0f} core-hours by the model" in scenes
    assert f"about {18 * pair('default'):.1f} core-hours by the cost model" in " ".join(text("docs/study.md").split())
    paper = estimate(resolve("paper", "polyhedra"))["core_hours"]
    old = estimate(resolve("paper", "polyhedra"), kernel_path="pyrunner")["core_hours"]
    assert f"about **{paper:.0f} core-hours per S1 seed**" in scenes and f"(about {old:.0f} on the `PyRunner` path)" in scenes
    assert f"{paper:.0f} × (0.045 + 0.955/64) ≈ {paper * (0.045 + 0.955 / 64):.0f} hours" in scenes
    assert f"{paper:.0f} × (0.045 + 0.955/7.1) ≈ {paper * (0.045 + 0.955 / 7.1):.0f} hours" in scenes
    assert f"{old:.0f} × (0.37 + 0.63/7.1) ≈ {old * (0.37 + 0.63 / 7.1):.0f} hours" in scenes
    s1 = estimate(resolve("intermediate", "polyhedra"))["core_hours"]
    s2 = estimate(resolve("intermediate", "spheres"))["core_hours"]
    assert f"(16 × ({s1:.2f} + {s2:.2f}))" in scenes
    study = " ".join(text("docs/study.md").split())
    assert f"3 + 3 seeds, about {3 * pair('intermediate'):.1f} core-hours by the cost model" in study
    # the size front: 3 + 3 seeds at each of 200, 1000 and 5000 grains
    front = 3 * (pair("small") + pair("default") + pair("intermediate"))
    makefile = " ".join(text("Makefile").replace("#", " ").split())
    assert f"3 + 3 seeds each, about {front:.1f} core-hours by the model" in makefile


def test_the_scene_parameters_the_docs_quote():
    from yade_scripts.scene.parameters import PARAMETERS

    d = {q.name: q.default for q in PARAMETERS}
    scenes = " ".join(text("docs/scenes.md").split())
    assert f"`iso_tolerance` ({d['iso_tolerance']:.0%})".replace("%", " %") in scenes
    assert f"the unbalanced force below {d['unbalanced_tolerance']:g}" in scenes
    assert f"ε1 = `final_strain` ({d['final_strain']:g})" in scenes
    assert f"`initial_fraction` of the grains themselves ({d['initial_fraction']:g})" in scenes
    assert f"(I_c = {d['compaction_inertial_number']:g})" in scenes
    assert f"every `checkpoint_seconds` of wall time (default {d['checkpoint_seconds']:g};" in scenes
    assert d["wall_friction"] == 0.0 and d["friction"] == 0.5 and "friction 0.5 between particles and 0 with the walls" in scenes
    assert f"margin `verlet_skin` × mean d = {d['verlet_skin']:g} d" in " ".join(text("docs/kernel.md").split())
