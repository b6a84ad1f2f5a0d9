"""The docstrings of the analysis library's core modules and of the run
machinery a user calls (one writer per run, the run's state and rule):
every public function and class has numpydoc sections (Parameters and Returns, or
Attributes for a data class), and their Examples run and give what they
show (doctest)."""
import doctest
import importlib
import inspect
import io

import pytest

#: the analysis library's modules whose public API is documented in numpydoc
NUMPYDOC = tuple(f"postproc.{m}" for m in ("stress", "fabric", "angular", "coordination", "networks", "pertype",
                                            "strain", "statistics", "analysis", "axes", "periodic", "contactset",
                                            "contacttypes", "contactpoints", "commonplane", "polygons",
                                            "lmgc90shape", "lmgc90count", "footprint",
                                            "classify", "columns", "cdpoints", "lmgc90files")) + tuple(f"yade_scripts.{m}" for m in (
    "runs.runlock", "runs.runstate", "runs.checkpoint", "runs.attempt", "launch.pool", "launch.task", "launch.slurm",
    "campaign.archive", "campaign.archive_store", "campaign.runfolders")) + tuple(
    f"lmgc90.{m}" for m in ("grains", "cdcontacts", "cdcontrol", "cdmodel", "cdstart", "cdsystem"))
#: the core modules whose every public function shows a runnable example
EXAMPLES = tuple(f"postproc.{m}" for m in ("stress", "fabric", "angular", "strain", "coordination", "networks",
                                           "pertype", "statistics")) + ("yade_scripts.runs.runlock", "yade_scripts.runs.runstate") + tuple(
    f"lmgc90.{m}" for m in ("grains", "cdcontacts", "cdcontrol"))


def public(module):
    mod = importlib.import_module(module)
    for name, obj in vars(mod).items():
        if name.startswith("_") or getattr(obj, "__module__", None) != mod.__name__:
            continue
        if inspect.isfunction(obj) or inspect.isclass(obj):
            yield name, obj


def sections(doc):
    """The numpydoc section titles of a docstring (a title line underlined
    by dashes of the same length)."""
    lines = inspect.cleandoc(doc or "").split("\n")
    return {a.strip() for a, b in zip(lines, lines[1:]) if b.strip() and set(b.strip()) == {"-"}
            and len(b.strip()) == len(a.strip())}


@pytest.mark.parametrize("module", NUMPYDOC)
def test_every_public_definition_has_numpydoc_sections(module):
    missing = []
    for name, obj in public(module):
        have = sections(obj.__doc__)
        need = {"Attributes"} if inspect.isclass(obj) else {"Parameters", "Returns"}
        if inspect.isfunction(obj) and not inspect.signature(obj).parameters:
            need = {"Returns"}
        if not need <= have:
            missing.append(f"{name}: {sorted(need - have)}")
        if inspect.isclass(obj):
            for mname, meth in vars(obj).items():
                if not mname.startswith("_") and inspect.isfunction(meth) and "Returns" not in sections(meth.__doc__):
                    missing.append(f"{name}.{mname}: ['Returns']")
    assert not missing, "without numpydoc sections: " + "; ".join(missing)


@pytest.mark.parametrize("module", EXAMPLES)
def test_the_examples_run(module):
    mod = importlib.import_module(module)
    finder = doctest.DocTestFinder()
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    out = io.StringIO()
    tested = set()
    for test in finder.find(mod, mod.__name__):
        if test.examples:
            tested.add(test.name[len(mod.__name__) + 1:].split(".")[0] if test.name != mod.__name__ else test.name)
            runner.run(test, out=out.write)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, out.getvalue()
    functions = {name for name, obj in public(module) if inspect.isfunction(obj)}
    assert functions <= tested, f"public functions without an example: {sorted(functions - tested)}"


#: entry points of the other modules a user calls, held to the same rule one
#: by one (their modules are not yet all written that way)
SHAPES_ENTRY_POINTS = tuple(f"shapes.{name}" for name in (
    "library.ShapeLibrary", "library.write_library", "engine.ContactEngine",
    "generate.Recipe", "generate.generate_shape", "generate.generate_library",
    "match.generate_like", "match.stretch_to", "match.smoothed_bootstrap",
    "hullreduce.Budget", "meshimport.ImportedGrain", "meshimport.read_mesh", "meshimport.merge_vertices",
    "meshimport.components", "meshimport.mesh_volume", "meshimport.check_closed", "hullreduce.distance_to_convex",
    "hullreduce.hausdorff_to_convex", "hullreduce.thin_points", "hullreduce.reduce_hull", "meshimport.import_mesh",
    "meshimport.mesh_files", "meshimport.import_paths",
    "descriptors.grain_descriptors", "descriptors.library_descriptors", "descriptors.dihedral_angles",
    "descriptors.principal_extents", "descriptors.library_edge_angles", "descriptors.compare",
    "polyhedron.Polyhedron", "polyhedron.polyhedron_from_points", "polyhedron.hull", "polyhedron.check_polyhedron",
    "polyhedron.normalise", "polyhedron.geometric_faces", "polyhedron.bend_angles", "polyhedron.edge_triangles",
    "polyhedron.triangle_normals",
    "overlap.pair_overlap", "overlap.wall_overlap", "overlap.batch_overlap", "overlap.batch_wall",
    "overlap.ShapeTable", "overlap.OrientedGrains", "overlap.rotation_matrices",
    "sections.polyhedron_section", "sections.sphere_section", "sections.polygon_area", "sections.plane_basis",
    "sections.edges_of",
    "sizes.class_counts", "sizes.sample_diameters",
    "report.library_stats", "report.descriptor_table", "report.budget_text", "report.study_section",
    "stones.check_checkout", "stones.build_stone_library"))
YADE_ENTRY_POINTS = ("yade_scripts.launch.slurm.estimate", "yade_scripts.campaign.presets.resolve",
                     "yade_scripts.campaign.generate.generate", "yade_scripts.launch.pool.Job", "yade_scripts.launch.pool.run_pool",
                     "yade_scripts.runs.runstate.judge", "yade_scripts.campaign.study.run_samples", "yade_scripts.campaign.study.collect",
                     "yade_scripts.scene.parameters.Parameter", "yade_scripts.scene.parameters.coerce",
                     "yade_scripts.scene.parameters.check", "yade_scripts.scene.parameters.changed",
                     "yade_scripts.scene.servo.wall_stresses", "yade_scripts.scene.servo.servo_rates",
                     "yade_scripts.scene.servo.wall_velocities", "yade_scripts.scene.timestep.inertial_strain_rate",
                     "yade_scripts.scene.timestep.rotational_mass", "yade_scripts.scene.timestep.critical_time_step",
                     "yade_scripts.runs.host.host_info", "yade_scripts.runs.host.cpu_from_cpuinfo",
                     "yade_scripts.launch.resources.memory_mb", "yade_scripts.launch.resources.check_memory",
                     "yade_scripts.launch.slurm.write_slurm", "yade_scripts.launch.slurm.submit", "yade_scripts.launch.slurm.queue_states",
                     "yade_scripts.launch.slurm.record_job", "yade_scripts.launch.slurm.recorded_jobs",
                     "yade_scripts.launch.slurm.time_seconds", "yade_scripts.launch.slurm.check_options",
                     "yade_scripts.launch.batch.TableLine", "yade_scripts.launch.batch.table_lines", "yade_scripts.launch.batch.read_table",
                     "yade_scripts.launch.batch.dump_of", "yade_scripts.launch.batch.run_batch", "yade_scripts.campaign.sweeps.run_front",
                     "yade_scripts.campaign.sweeps.write_table", "yade_scripts.yadeplugin.status",
                     "yade_scripts.yadeplugin.build", "yade_scripts.yadeplugin.environment")
LMGC90_ENTRY_POINTS = ("lmgc90.study.estimate", "lmgc90.study.slurm_time")
ENTRY_POINTS = SHAPES_ENTRY_POINTS + YADE_ENTRY_POINTS + LMGC90_ENTRY_POINTS


@pytest.mark.parametrize("dotted", ENTRY_POINTS)
def test_entry_points_have_numpydoc_and_a_running_example(dotted):
    module, name = dotted.rsplit(".", 1)
    mod = importlib.import_module(module)
    obj = getattr(mod, name)
    need = {"Parameters", "Attributes", "Examples"} if inspect.isclass(obj) else {"Parameters", "Returns", "Examples"}
    assert need <= sections(obj.__doc__), dotted
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS)
    out = io.StringIO()
    tests = [t for t in doctest.DocTestFinder().find(obj, dotted, globs=vars(mod)) if t.examples]
    assert tests, dotted
    for t in tests:
        runner.run(t, out=out.write)
    assert runner.summarize(verbose=False).failed == 0, out.getvalue()


def _public_definitions(package):
    """(file, dotted name) of every public top-level function and class of a
    package's modules and of every public method of those classes (read with
    ast: the scene scripts import YADE, which the venv does not have)."""
    import ast
    import pathlib

    root = pathlib.Path(__file__).resolve().parent.parent / package
    for path in sorted(root.rglob("*.py")):
        if any(part.startswith("_build") or part in ("include", "vendor") for part in path.parts):
            continue
        tree = ast.parse(path.read_text())
        for node in tree.body:
            if isinstance(node, (ast.FunctionDef, ast.ClassDef)) and not node.name.startswith("_"):
                yield path, node.name, node
                if isinstance(node, ast.ClassDef):
                    for m in node.body:
                        if isinstance(m, ast.FunctionDef) and not m.name.startswith("_"):
                            yield path, f"{node.name}.{m.name}", m


@pytest.mark.parametrize("package", ("shapes", "yade_scripts", "lmgc90"))
def test_no_public_definition_without_a_docstring(package):
    import ast

    bare = [f"{path.name}:{name}" for path, name, node in _public_definitions(package) if not ast.get_docstring(node)]
    assert not bare, f"{len(bare)} public definitions of {package} without a docstring: " + ", ".join(bare)
