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
                                            "contacttypes", "contactpoints", "commonplane", "footprint",
                                            "classify", "cdpoints", "lmgc90files")) + tuple(f"yade_scripts.{m}" for m in (
    "runlock", "runstate", "checkpoint", "attempt", "pool", "task", "archive", "slurm")) + tuple(
    f"lmgc90.{m}" for m in ("grains", "cdcontacts", "cdcontrol", "cdmodel", "cdstart", "cdsystem"))
#: the core modules whose every public function shows a runnable example
EXAMPLES = tuple(f"postproc.{m}" for m in ("stress", "fabric", "angular", "strain", "coordination", "networks",
                                           "pertype", "statistics")) + ("yade_scripts.runlock", "yade_scripts.runstate") + tuple(
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
            tested.add(test.name.split(".")[2] if test.name.count(".") >= 2 else test.name)
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
    "meshimport.Budget", "meshimport.ImportedGrain", "meshimport.read_mesh", "meshimport.merge_vertices",
    "meshimport.components", "meshimport.mesh_volume", "meshimport.check_closed", "meshimport.distance_to_convex",
    "meshimport.hausdorff_to_convex", "meshimport.thin_points", "meshimport.reduce_hull", "meshimport.import_mesh",
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
YADE_ENTRY_POINTS = ("yade_scripts.slurm.estimate", "yade_scripts.presets.resolve",
                     "yade_scripts.generate.generate", "yade_scripts.pool.Job", "yade_scripts.pool.run_pool",
                     "yade_scripts.runstate.judge", "yade_scripts.study.run_samples", "yade_scripts.study.collect",
                     "yade_scripts.parameters.Parameter", "yade_scripts.parameters.coerce",
                     "yade_scripts.parameters.check", "yade_scripts.parameters.changed",
                     "yade_scripts.servo.wall_stresses", "yade_scripts.servo.servo_rates",
                     "yade_scripts.servo.wall_velocities", "yade_scripts.timestep.inertial_strain_rate",
                     "yade_scripts.timestep.rotational_mass", "yade_scripts.timestep.critical_time_step",
                     "yade_scripts.host.host_info", "yade_scripts.host.cpu_from_cpuinfo",
                     "yade_scripts.resources.memory_mb", "yade_scripts.resources.check_memory",
                     "yade_scripts.slurm.write_slurm", "yade_scripts.slurm.submit", "yade_scripts.slurm.queue_states",
                     "yade_scripts.slurm.record_job", "yade_scripts.slurm.recorded_jobs",
                     "yade_scripts.slurm.time_seconds", "yade_scripts.slurm.check_options",
                     "yade_scripts.batch.TableLine", "yade_scripts.batch.table_lines", "yade_scripts.batch.read_table",
                     "yade_scripts.batch.dump_of", "yade_scripts.batch.run_batch", "yade_scripts.front.run_front",
                     "yade_scripts.front.write_table", "yade_scripts.yadeplugin.status",
                     "yade_scripts.yadeplugin.build", "yade_scripts.yadeplugin.environment")
ENTRY_POINTS = SHAPES_ENTRY_POINTS + YADE_ENTRY_POINTS


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
