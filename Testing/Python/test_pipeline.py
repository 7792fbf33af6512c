"""Pipeline XML files through the ``anatomesh`` command: the thorax job runs and writes what it
says; every kind of mistake exits non-zero with a message naming the file and the line."""
import csv
import io
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest

import numpy as np

SOURCE = os.path.abspath(os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")))
TMP = os.environ.get("ANATOMESH_TEST_TMP", tempfile.gettempdir())
CLI = [sys.executable, os.path.join(SOURCE, "Wrapping", "anatomesh")]


def run(*args, env=None):
    p = subprocess.run(CLI + list(args), capture_output=True, text=True, timeout=600, env=env)
    return p.returncode, p.stdout, p.stderr


def pipeline_file(name, body):
    path = os.path.join(TMP, name)
    with open(path, "w") as f:
        f.write(textwrap.dedent(body).lstrip())
    return path


class ThoraxJob(unittest.TestCase):
    def test_thorax_pipeline_writes_outputs(self):
        out = os.path.join(TMP, "thorax_job")
        shutil.rmtree(out, ignore_errors=True)
        code, stdout, stderr = run("run", os.path.join(SOURCE, "Examples", "Pipelines", "thorax.xml"),
                                   "--output", out, "--set", "spacing=4", "--set", "tolerance=1", "--set", "size=8")
        self.assertEqual(code, 0, stderr)
        # 10 files of the meshing chain; the heartbeat: the landmarks, the ventricles' tags, heart and
        # body-surface time series (101 frames + .pvd each), the ECG and its reading.
        self.assertIn("Wrote 220 file(s)", stdout)
        for name in ("thorax_heart.pvd", "thorax_body_surface.pvd", "thorax_heart_0100.vtu", "thorax_ecg.csv",
                     "thorax_ecg_features.csv", "thorax_landmarks.vtp", "thorax_ventricular_tags.vtp",
                     "thorax_opencarp.pts", "thorax_opencarp.elem", "thorax_opencarp.lon",
                     "thorax_opencarp.LVEndocardium.surf", "thorax_opencarp.Epicardium.vtx", "thorax_tets.xdmf",
                     "thorax_tets_facets.xdmf"):
            self.assertTrue(os.path.exists(os.path.join(out, name)), name)
        with open(os.path.join(out, "thorax_ecg.csv")) as f:
            rows = f.read().splitlines()
        self.assertEqual(len(rows), 502)  # header + 0, 1, ..., 500 ms
        self.assertTrue(rows[0].startswith("Time_ms,I_mV,II_mV,III_mV"), rows[0])  # units in the header
        self.assertRegex(stdout, r"ECG: QRS \d+ ms \(normal 70-110[^)]*\), QT \d+ ms")
        self.assertIn("phantom", stderr)  # progress lines
        # The timing table: every filter with its own seconds, the output files and the rest, adding
        # up to the run's time; the same figures in the run marker.
        table = stdout[stdout.index("Seconds per filter"):].splitlines()
        names = ["phantom", "snake", "segmentation", "dice", "surface", "smooth", "metric", "remesh",
                 "save_surface_mesh", "save_ct", "save_truth", "save_labels", "tets", "quality", "save_volume_mesh",
                 "save_gmsh", "landmarks", "fibres", "save_xdmf", "save_opencarp", "heart", "ecg", "torso", "(outputs)", "(other)"]
        self.assertEqual([l.split()[0] for l in table[1:len(names) + 1]], names)
        self.assertRegex(stdout, r"heart +ReactionEikonalSolver +[0-9.]+ s +[0-9.]+ % +[0-9.]+ +\(\d+ runs\)")
        # Cores kept busy: CPU seconds per wall second, more than none and at most the machine's
        # cores (plus the clocks' granularity).
        tets = next(l for l in table if l.split()[0] == "tets").split()
        self.assertTrue(0.0 < float(tets[6]) <= os.cpu_count() + 0.1, tets)
        total = float(table[len(names) + 1].split()[1])
        done = float(re.search(r"Done in ([0-9.]+) s", stdout).group(1))
        self.assertLessEqual(total, done + 0.05)
        with open(os.path.join(out, "anatomesh-run.json")) as f:
            record = json.load(f)
        stages = record["stage_seconds"]
        self.assertEqual(sorted(stages), sorted(names))
        self.assertAlmostEqual(sum(stages.values()), record["seconds"], delta=0.05)
        self.assertLess(stages["(other)"], 0.2 * record["seconds"])  # the filters account for the run
        self.assertGreater(stages["tets"], 0.0)
        self.assertGreater(stages["(outputs)"], 0.0)
        # Warnings in a log: one plain line naming the filter, no terminal colour codes.
        self.assertIn("anatomesh: warning: surface: ", stderr)
        self.assertNotIn("\x1b[", stderr)
        import anatomesh
        from vtkmodules.util.numpy_support import vtk_to_numpy

        def read(name):
            reader = anatomesh.amImageReader()
            reader.SetFileName(os.path.join(out, name))
            reader.Update()
            self.assertEqual(reader.GetOutput().GetDimensions(), (80, 60, 53))
            return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())

        truth = read("thorax_truth_labels.nii.gz")
        self.assertEqual(sorted(set(truth.tolist())), list(range(11)))
        # The segmentation has every organ of the simulation domain and, even at 4 mm, each overlaps the truth;
        # the Dice table that scores it is written and printed.
        labels = read("thorax_labels.nii.gz")
        self.assertEqual(sorted(set(labels.tolist())), list(range(11)))
        # Names and colours beside it; nibabel reads the same voxels at the same place (RAS = LPS with x, y negated).
        with open(os.path.join(out, "thorax_labels.ctbl")) as f:
            table = [line.split() for line in f if not line.startswith("#")]
        self.assertEqual([row[:2] for row in table[5:7]], [["5", "Myocardium"], ["6", "LeftVentricleBlood"]])
        with open(os.path.join(out, "thorax_labels.itksnap.txt")) as f:
            snap = [line.split(None, 7) for line in f if not line.startswith("#")]
        self.assertEqual((snap[5][0], snap[5][7].strip()), ("5", '"Myocardium"'))
        try:
            import nibabel
        except ImportError:
            nibabel = None
        if nibabel is not None:
            image = nibabel.load(os.path.join(out, "thorax_labels.nii.gz"))
            voxels = np.asarray(image.dataobj)
            self.assertEqual(voxels.shape, (80, 60, 53))
            np.testing.assert_array_equal(voxels.transpose(2, 1, 0).ravel(), labels)
            reader = anatomesh.amImageReader()
            reader.SetFileName(os.path.join(out, "thorax_labels.nii.gz"))
            reader.Update()
            origin = reader.GetOutput().GetOrigin()
            np.testing.assert_allclose(image.affine[:3, 3], [-origin[0], -origin[1], origin[2]], atol=1e-4)
        for label in range(1, 11):
            a, b = labels == label, truth == label
            self.assertGreater(2.0 * (a & b).sum() / (a.sum() + b.sum()), 0.8, label)
        with open(os.path.join(out, "thorax_dice.csv")) as f:
            dice = [line.strip().split(",") for line in f]
        self.assertEqual(dice[0][:4], ["Label", "Volume_mm3", "ReferenceVolume_mm3", "Dice"])
        self.assertEqual([r[0] for r in dice[1:]], [str(label) for label in range(1, 11)] + ["-1"])
        self.assertIn("Dice", stdout)
        # The remeshed surface of every organ, within the tolerance.
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
        surface = vtkXMLPolyDataReader()
        surface.SetFileName(os.path.join(out, "thorax_surface.vtp"))
        surface.Update()
        pairs = vtk_to_numpy(surface.GetOutput().GetCellData().GetArray("Labels"))
        self.assertEqual(set(pairs.ravel().tolist()), set(range(11)))
        # Known limit (README): where every refinement would make triangles cross, remeshing stops
        # above the tolerance (1 mm here) with a warning; the field data says by how much.
        self.assertLessEqual(surface.GetOutput().GetFieldData().GetArray("Hausdorff").GetValue(0), 1.4)
        self.assertTrue(os.path.getsize(os.path.join(out, "thorax_surface.mesh")) > 0)
        # The tetrahedral mesh of every organ and its quality table (the paper's Table 1); the simulation
        # runs on it (the heart time series holds the segmented myocardium's nodes).
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
        tets = vtkXMLUnstructuredGridReader()
        tets.SetFileName(os.path.join(out, "thorax_tets.vtu"))
        tets.Update()
        regions = vtk_to_numpy(tets.GetOutput().GetCellData().GetArray("Region"))
        self.assertEqual(sorted(set(regions.tolist())), list(range(1, 11)))
        self.assertGreater(vtk_to_numpy(tets.GetOutput().GetCellData().GetArray("Volume")).min(), 0)
        with open(os.path.join(out, "thorax_quality.csv")) as f:
            rows = [line.strip().split(",") for line in f]
        self.assertEqual(rows[0][:4], ["Region", "np", "nt", "ne"])
        self.assertEqual([r[0] for r in rows[1:]], [str(label) for label in range(1, 11)] + ["-1"])
        self.assertEqual(int(rows[-1][3]), tets.GetOutput().GetNumberOfCells())
        self.assertIn("MeanQuality", stdout)  # the table is printed at the end of the run
        self.assertTrue(os.path.getsize(os.path.join(out, "thorax_tets.mesh")) > 0)
        with open(os.path.join(out, "thorax_tets.msh")) as f:
            self.assertEqual(f.read(30).split("\n")[:2], ["$MeshFormat", "4.1 0 8"])
        leftovers = [f for f in os.listdir(out) if ".tmp" in f]
        self.assertEqual(leftovers, [])

    def test_paper_table_pipeline_has_no_sliver(self):
        # The paper's Table 1 case (the ten-organ phantom's exact labels) at 2 mm: every organ a region,
        # worst Q <= 10 and every dihedral angle >= 10 degrees once the surface may move 0.5 mm.
        out = os.path.join(TMP, "paper_table")
        shutil.rmtree(out, ignore_errors=True)
        code, stdout, stderr = run("run", os.path.join(SOURCE, "Examples", "Pipelines", "paper_table.xml"),
                                   "--output", out, "--set", "spacing=2", "--set", "deviation=0.5")
        self.assertEqual(code, 0, stderr)
        table = np.genfromtxt(os.path.join(out, "phantom_quality.csv"), delimiter=",", names=True)
        self.assertEqual(sorted(int(r) for r in table["Region"] if r > 0), list(range(1, 11)))
        whole = table[table["Region"] == -1][0]
        self.assertLessEqual(whole["MaximumQuality"], 10.0)
        self.assertGreaterEqual(whole["MinimumDihedralAngle_deg"], 10.0)  # the header's units
        self.assertLess(whole["MeanQuality"], 1.45)
        self.assertEqual(whole["InvertedTetrahedra"], 0)

    def test_seed_points_source_feeds_the_snake(self):
        """ParaView's indexed repeatable properties (SeedPoints' Positions and Labels) in a pipeline file."""
        out = os.path.join(TMP, "seed_points_job")
        shutil.rmtree(out, ignore_errors=True)
        path = pipeline_file("seed_points.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="phantom" type="ThoraxPhantomSource">
                <Property name="Spacing" value="4 4 4"/>
              </Filter>
              <Filter name="seeds" type="SeedPoints">
                <Property name="Positions" value="29.4 -24.1 -28  -15 -25 -28"/>
                <Property name="Labels" value="16 17"/>
              </Filter>
              <Filter name="snake" type="SnakeSegmentation">
                <Input from="phantom" port="CT"/>
                <Input name="SeedPoints" from="seeds"/>
              </Filter>
              <Output from="snake" file="${output}/organs.vti"/>
            </AnatomeshPipeline>""")
        code, _, stderr = run("run", path, "--output", out, "--quiet")
        self.assertEqual(code, 0, stderr)
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkIOXML import vtkXMLImageDataReader
        reader = vtkXMLImageDataReader()
        reader.SetFileName(os.path.join(out, "organs.vti"))
        reader.Update()
        labels = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("Labels"))
        self.assertEqual(sorted(set(labels.tolist())), [0, 16, 17])
        # The two blood pools: about 65 and 27 cm3 in the phantom (4 mm voxels).
        self.assertGreater((labels == 16).sum() * 64 / 1000.0, 40)
        self.assertGreater((labels == 17).sum() * 64 / 1000.0, 15)

    def test_defaults_can_name_files_beside_the_pipeline(self):
        folder = os.path.join(TMP, "beside_pipeline")
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        path = os.path.join(folder, "beside.xml")
        with open(path, "w") as f:
            f.write(textwrap.dedent("""
                <AnatomeshPipeline version="1">
                  <Variable name="here" default="${pipeline_dir}/results"/>
                  <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
                  <Filter name="w" type="ImageWriter">
                    <Input from="p" port="Labels"/>
                    <Property name="FileName" value="${here}/labels.nii.gz"/>
                  </Filter>
                </AnatomeshPipeline>""").lstrip())
        p = subprocess.run(CLI + ["run", path, "--quiet", "--output", os.path.join(folder, "out")],
                           capture_output=True, text=True, timeout=600, cwd=tempfile.gettempdir())
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertTrue(os.path.exists(os.path.join(folder, "results", "labels.nii.gz")))
        # A pipeline's own default for "output" holds when the command line gives none.
        with open(path, "w") as f:
            f.write(textwrap.dedent("""
                <AnatomeshPipeline version="1">
                  <Variable name="output" default="${pipeline_dir}/default_out"/>
                  <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
                  <Output from="p" port="CT" file="${output}/ct.vti"/>
                </AnatomeshPipeline>""").lstrip())
        p = subprocess.run(CLI + ["run", path, "--quiet"], capture_output=True, text=True, timeout=600,
                           cwd=tempfile.gettempdir())
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertTrue(os.path.exists(os.path.join(folder, "default_out", "ct.vti")))

    def test_meshio_reads_every_mesh_output(self):
        try:
            import meshio
        except ImportError:
            self.skipTest("meshio is not installed (python3-meshio)")
        path = pipeline_file("interop.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource">
                <Property name="Spacing" value="8 8 8"/>
              </Filter>
              <Filter name="surface" type="LabelSurface"><Input from="p" port="Labels"/></Filter>
              <Filter name="tets" type="Tetrahedralize"><Input from="surface"/></Filter>
              <Output from="tets" port="Mesh" file="${output}/mesh.vtu"/>
              <Filter name="medit" type="MeditWriter">
                <Input from="tets" port="Mesh"/>
                <Property name="FileName" value="${output}/mesh.mesh"/>
              </Filter>
              <Filter name="gmsh" type="GmshWriter">
                <Input from="tets" port="Mesh"/>
                <Property name="FileName" value="${output}/mesh.msh"/>
              </Filter>
            </AnatomeshPipeline>""")
        out = os.path.join(TMP, "interop_out")
        code, _, stderr = run("run", path, "--output", out, "--quiet")
        self.assertEqual(code, 0, stderr)
        counts = {}
        for name in ("mesh.vtu", "mesh.mesh", "mesh.msh"):
            mesh = meshio.read(os.path.join(out, name))
            counts[name] = sum(len(block.data) for block in mesh.cells if block.type == "tetra")
        self.assertGreater(counts["mesh.vtu"], 1000)
        self.assertEqual(len(set(counts.values())), 1, counts)  # the same tetrahedra in every format
        # The .vtu's provenance: UTF-8 text as bytes, one line per step.
        vtu = meshio.read(os.path.join(out, "mesh.vtu"))
        provenance = bytes(vtu.field_data["Provenance"].astype(np.uint8)).decode("utf-8")
        self.assertIn("Tetrahedralize", provenance)
        self.assertIn("Region", vtu.cell_data)
        # The .msh's physical groups: a volume per organ and a surface per interface and boundary,
        # as meshio and Gmsh itself read them; the same triangles as the .mesh's references.
        msh = meshio.read(os.path.join(out, "mesh.msh"))
        groups = {name: tuple(v) for name, v in msh.field_data.items()}
        volumes = {n: t for n, (t, dim) in groups.items() if dim == 3}
        surfaces = {n: t for n, (t, dim) in groups.items() if dim == 2}
        self.assertEqual(set(volumes.values()), set(np.unique(vtu.cell_data["Region"][0]).tolist()))
        self.assertIn("Myocardium", volumes)
        self.assertTrue(any(n.endswith("| Outside") for n in surfaces), surfaces)
        self.assertTrue(all(t // 1000 in volumes.values() for t in surfaces.values()), surfaces)
        medit = meshio.read(os.path.join(out, "mesh.mesh"))
        triangles = lambda m: sum(len(b.data) for b in m.cells if b.type == "triangle")
        self.assertEqual(triangles(msh), triangles(medit))
        try:
            import gmsh
        except ImportError:
            return
        gmsh.initialize(["gmsh", "-v", "0"])
        try:
            gmsh.open(os.path.join(out, "mesh.msh"))
            read = {gmsh.model.getPhysicalName(dim, tag): (tag, dim) for dim, tag in gmsh.model.getPhysicalGroups()}
            self.assertEqual(read, groups)
            tetrahedra = sum(len(gmsh.model.mesh.getElements(3, tag)[1][0]) for _, tag in gmsh.model.getEntities(3))
            self.assertEqual(tetrahedra, counts["mesh.vtu"])
            # Every volume knows the surfaces that bound it.
            for _, tag in gmsh.model.getEntities(3):
                self.assertTrue(gmsh.model.getBoundary([(3, tag)], oriented=False), tag)
        finally:
            gmsh.finalize()

    def test_a_coarse_run_says_it_misses_the_element_bars(self):
        # The phantom at 4 mm remeshed to 10 mm triangles within 2 mm and meshed with the defaults keeps
        # slivers the surface forces: the run says so, with the worst element's place.
        path = pipeline_file("coarse_bars.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="4 4 4"/></Filter>
              <Filter name="surface" type="LabelSurface"><Input from="p" port="Labels"/></Filter>
              <Filter name="smooth" type="SurfaceSmoothing"><Input from="surface" port="Surface"/></Filter>
              <Filter name="remesh" type="MetricRemeshing">
                <Input from="smooth"/>
                <Property name="TargetSize" value="10"/>
                <Property name="Tolerance" value="2"/>
              </Filter>
              <Filter name="tets" type="Tetrahedralize"><Input from="remesh"/></Filter>
              <Filter name="q" type="MeshQuality"><Input from="tets" port="Mesh"/></Filter>
              <Output from="q" port="Table" file="${output}/q.csv"/>
            </AnatomeshPipeline>""")
        code, stdout, stderr = run("run", path, "--output", os.path.join(TMP, "coarse_bars"))
        self.assertEqual(code, 0, stderr)
        with open(os.path.join(TMP, "coarse_bars", "q.csv")) as f:
            whole = [r for r in csv.DictReader(f) if r["Region"] == "-1"][0]
        missed = float(whole["MaximumQuality"]) > 10 or float(whole["MinimumDihedralAngle_deg"]) < 10
        with open(os.path.join(TMP, "coarse_bars", "anatomesh-run.json")) as f:
            recorded = json.load(f)["warnings"]
        if missed:
            self.assertRegex(stderr, r"warning: tets: the mesh misses the element bars: \d+ tetrahedra above Q 10 "
                                     r"\(worst [0-9.]+\), \d+ with a dihedral angle under 10 degrees \(smallest "
                                     r"[0-9.]+\); the worst, tetrahedron \d+, at \(")
            # ... and the run's marker keeps it (the report lists it).
            self.assertTrue(any(w.startswith("tets: the mesh misses the element bars") for w in recorded), recorded)
        else:
            self.assertNotIn("misses the element bars", stderr)

    def test_quality_of_a_medit_mesh_read_back(self):
        # A .mesh read back carries its interface triangles beside the tetrahedra: MeshQuality measures
        # the tetrahedra (the same table as on the mesh written).
        path = pipeline_file("readback.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              <Filter name="surface" type="LabelSurface"><Input from="p" port="Labels"/></Filter>
              <Filter name="tets" type="Tetrahedralize"><Input from="surface"/></Filter>
              <Filter name="q" type="MeshQuality"><Input from="tets" port="Mesh"/></Filter>
              <Output from="q" port="1" file="${output}/written.csv"/>
              <Filter name="medit" type="MeditWriter">
                <Input from="tets" port="Mesh"/><Property name="FileName" value="${output}/mesh.mesh"/>
              </Filter>
            </AnatomeshPipeline>""")
        out = os.path.join(TMP, "readback_out")
        code, _, stderr = run("run", path, "--output", out, "--quiet")
        self.assertEqual(code, 0, stderr)
        again = pipeline_file("readback2.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="r" type="MeditReader"><Property name="FileName" value="%s"/></Filter>
              <Filter name="q" type="MeshQuality"><Input from="r"/></Filter>
              <Output from="q" port="1" file="${output}/read.csv"/>
            </AnatomeshPipeline>""" % os.path.join(out, "mesh.mesh"))
        code, _, stderr = run("run", again, "--output", out, "--quiet")
        self.assertEqual(code, 0, stderr)
        with open(os.path.join(out, "written.csv")) as a, open(os.path.join(out, "read.csv")) as b:
            self.assertEqual(a.read(), b.read())

    def test_vtk_xml_output_and_filters_listing(self):
        path = pipeline_file("vtkxml.xml", """
            <AnatomeshPipeline version="1">
              <Variable name="output" default="x"/>
              <Filter name="p" type="ThoraxPhantomSource">
                <Property name="Spacing" value="8 8 8"/>
              </Filter>
              <Output from="p" port="Labels" file="${output}/labels.vti"/>
            </AnatomeshPipeline>""")
        out = os.path.join(TMP, "vtkxml_out")
        # What a killed run left: a temporary of a process that is gone, which this run removes.
        os.makedirs(out, exist_ok=True)
        gone = subprocess.Popen([sys.executable, "-c", "pass"])
        gone.wait()
        stale = os.path.join(out, ".labels.tmp%d.vti" % gone.pid)
        with open(stale, "w") as f:
            f.write("half")
        code, _, stderr = run("run", path, "--output", out, "--quiet")
        self.assertEqual(code, 0, stderr)
        self.assertTrue(os.path.getsize(os.path.join(out, "labels.vti")) > 0)
        self.assertFalse(os.path.exists(stale))
        code, stdout, _ = run("filters")
        self.assertEqual(code, 0)
        self.assertIn("ThoraxPhantomSource", stdout)

    def test_the_command_sets_the_allocator_and_keeps_a_users_own(self):
        # The command starts itself again with glibc's allocator set for large arrays (see
        # Wrapping/anatomesh); the run's marker says which settings the run had. A user's own
        # GLIBC_TUNABLES is left as it is.
        path = pipeline_file("allocator.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              <Output from="p" port="Labels" file="${output}/labels.vti"/>
            </AnatomeshPipeline>""")
        out = os.path.join(TMP, "allocator_out")
        plain = {k: v for k, v in os.environ.items() if k != "GLIBC_TUNABLES"}
        ours = ("glibc.malloc.hugetlb=1:glibc.malloc.mmap_max=0:glibc.malloc.trim_threshold=68719476736:"
                "glibc.malloc.arena_max=2")
        for tunables, expected in ((None, ours),
                                   ("glibc.malloc.tcache_count=6", "glibc.malloc.tcache_count=6")):
            env = dict(plain)
            if tunables is not None:
                env["GLIBC_TUNABLES"] = tunables
            code, _, stderr = run("run", path, "--output", out, "--quiet", env=env)
            self.assertEqual(code, 0, stderr)
            with open(os.path.join(out, "anatomesh-run.json")) as f:
                self.assertEqual(json.load(f)["glibc_tunables"], expected)


class ProgressLog(unittest.TestCase):
    def test_a_filter_run_per_frame_is_not_repeated(self):
        # In a log (not a terminal), a filter that runs once per frame (the heart and torso of a
        # time series) shows its first pass every 25 %; its time is in the summary's timing table.
        from anatomesh.cli import _Progress
        stream = io.StringIO()
        progress = _Progress(stream)
        for name, fraction in [("phantom", 0.0), ("phantom", 0.3), ("phantom", 1.0)]:
            progress(name, fraction)
        for frame in range(50):
            for name in ("heart", "torso"):
                progress(name, 0.0)
                progress(name, 1.0)
        progress(None, 1.0)
        lines = stream.getvalue().splitlines()
        self.assertEqual([l.split()[:2] for l in lines],
                         [["phantom", "0%"], ["phantom", "25%"], ["phantom", "100%"], ["heart", "0%"],
                          ["heart", "100%"], ["torso", "0%"], ["torso", "100%"]])

    def test_stage_clock_counts_each_stage_its_own_time(self):
        # A filter updated from inside another (nested Start/End events) pauses the outer one's clock.
        from anatomesh.watch import StageClock
        clock = StageClock()
        clock.start("outer")
        time.sleep(0.05)
        clock.start("inner")
        time.sleep(0.2)
        clock.stop("inner")
        time.sleep(0.05)
        clock.stop("outer")
        with clock.running("outer"):
            time.sleep(0.05)
        self.assertAlmostEqual(clock.seconds["inner"], 0.2, delta=0.05)
        self.assertAlmostEqual(clock.seconds["outer"], 0.15, delta=0.05)
        self.assertEqual(clock.runs, {"outer": 2, "inner": 1})
        clock.stop("never started")  # ignored, not an error
        self.assertNotIn("never started", clock.seconds)


class ReleasedData(unittest.TestCase):
    @staticmethod
    def pipeline(name, spacing, rest):
        """A pipeline of the phantom at 'spacing' mm and its label surface, then 'rest'."""
        return pipeline_file(name, """
            <AnatomeshPipeline version="1">
              <Variable name="output" default="x"/>
              <Filter name="phantom" type="ThoraxPhantomSource">
                <Property name="Spacing" value="%d %d %d"/>
              </Filter>
              <Filter name="surface" type="LabelSurface">
                <Input from="phantom" port="Labels"/>
              </Filter>
            """.rstrip(" ") % (spacing, spacing, spacing) + textwrap.indent(textwrap.dedent(rest).strip(), " " * 14)
                             + "\n            </AnatomeshPipeline>")

    def test_an_output_used_once_is_released_after_its_filter_ran(self):
        # The label map and the raw surface each feed one filter: freed once it has run (their
        # memory goes to the later stages), without running anything twice. What is written,
        # or feeds two steps, stays.
        from anatomesh.pipeline import Pipeline
        path = self.pipeline("release.xml", 6, """
            <Filter name="smooth" type="SurfaceSmoothing">
              <Input from="surface" port="Surface"/>
            </Filter>
            <Filter name="save_ct" type="ImageWriter">
              <Input from="phantom" port="CT"/>
              <Property name="FileName" value="${output}/ct.nii.gz"/>
            </Filter>
            <Output from="smooth" file="${output}/smooth.vtp"/>""")
        p = Pipeline(path, {"output": os.path.join(TMP, "release_out")})
        p.run()
        steps = {s.name: s.algorithm for s in p.steps}
        self.assertEqual({k: v for k, v in p.clock.runs.items() if k in steps}, {"phantom": 1, "surface": 1, "smooth": 1})
        labels, surface = steps["phantom"].GetOutputDataObject(1), steps["surface"].GetOutputDataObject(0)
        self.assertTrue(labels.GetDataReleased())
        self.assertEqual(labels.GetNumberOfPoints(), 0)
        self.assertTrue(surface.GetDataReleased())
        self.assertEqual(surface.GetNumberOfCells(), 0)
        ct, smooth = steps["phantom"].GetOutputDataObject(0), steps["smooth"].GetOutputDataObject(0)
        self.assertFalse(ct.GetDataReleased())
        self.assertGreater(ct.GetNumberOfPoints(), 0)
        self.assertFalse(smooth.GetDataReleased())
        self.assertGreater(smooth.GetNumberOfCells(), 0)
        self.assertGreater(os.path.getsize(os.path.join(TMP, "release_out", "smooth.vtp")), 0)
        # A filter run once per frame (the heart's time series) keeps its input: the mesh is made once.
        frames = self.pipeline("release_frames.xml", 4, """
            <Filter name="tets" type="Tetrahedralize">
              <Input from="surface"/>
              <Property name="ImproveQuality" value="0"/>
            </Filter>
            <Filter name="heart" type="FitzHughNagumoSolver">
              <Input from="tets" port="Mesh"/>
              <Property name="HeartRegions" value="5"/>
              <Property name="StimulusCenter" value="61 -51.5 -25"/>
              <Property name="EndTime" value="20"/>
              <Property name="OutputInterval" value="5"/>
            </Filter>
            <Output from="heart" file="${output}/heart.pvd"/>""")
        p = Pipeline(frames, {"output": os.path.join(TMP, "release_frames_out")})
        p.run()
        steps = {s.name: s.algorithm for s in p.steps}
        self.assertEqual(p.clock.runs["tets"], 1)
        self.assertGreater(p.clock.runs["heart"], 1)
        self.assertFalse(steps["tets"].GetOutputDataObject(0).GetDataReleased())
        self.assertTrue(steps["surface"].GetOutputDataObject(0).GetDataReleased())
        # build() alone releases nothing.
        algorithms = Pipeline(path, {"output": os.path.join(TMP, "release_out2")}).build()
        algorithms["smooth"].Update()
        self.assertFalse(algorithms["surface"].GetOutputDataObject(0).GetDataReleased())
        self.assertGreater(algorithms["surface"].GetOutputDataObject(0).GetNumberOfCells(), 0)


class DeprecatedNames(unittest.TestCase):
    def test_british_property_names_still_read_with_a_warning(self):
        path = pipeline_file("deprecated.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource">
                <Property name="Spacing" value="8 8 8"/>
              </Filter>
              <Filter name="s" type="LabelSurface">
                <Input from="p" port="Labels"/>
              </Filter>
              <Filter name="m" type="CurvatureMetric">
                <Input from="s"/>
                <Property name="NeighbourhoodRings" value="3"/>
              </Filter>
              <Output from="m" file="${output}/metric.vtp"/>
            </AnatomeshPipeline>""")
        out = os.path.join(TMP, "deprecated_out")
        code, _, stderr = run("run", path, "--output", out, "--quiet")
        self.assertEqual(code, 0, stderr)
        self.assertIn("property 'NeighbourhoodRings' is deprecated; use 'NeighborhoodRings'", stderr)
        self.assertTrue(os.path.getsize(os.path.join(out, "metric.vtp")) > 0)


class PipelineErrors(unittest.TestCase):
    def expect_error(self, name, body, *needles, args=()):
        path = pipeline_file(name, body)
        code, stdout, stderr = run("run", path, "--output", os.path.join(TMP, "err_" + name), *args)
        self.assertEqual(code, 1, "expected failure, got %d: %s" % (code, stderr))
        self.assertIn("anatomesh: error: " + path, stderr)
        for needle in needles:
            self.assertIn(needle, stderr)
        self.assertNotIn("Traceback", stderr)
        return stderr

    def test_output_over_an_input_is_refused(self):
        scan = os.path.join(TMP, "overwrite_me.nii.gz")
        src = pipeline_file("make_scan.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              <Filter name="w" type="ImageWriter">
                <Input from="p" port="Labels"/><Property name="FileName" value="%s"/>
              </Filter>
            </AnatomeshPipeline>""" % scan)
        self.assertEqual(run("run", src, "--quiet", "--output", os.path.join(TMP, "make_scan"))[0], 0)
        before = open(scan, "rb").read()
        # The same file through another spelling of its path.
        other = os.path.join(TMP, "..", os.path.basename(TMP), ".", "overwrite_me.nii.gz")
        self.expect_error("overwrite.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="r" type="ImageReader"><Property name="FileName" value="%s"/></Filter>
              <Filter name="w" type="ImageWriter">
                <Input from="r"/><Property name="FileName" value="%s"/>
              </Filter>
            </AnatomeshPipeline>""" % (scan, other), ":4: output", "would overwrite the input")
        self.assertEqual(open(scan, "rb").read(), before)

    def test_two_outputs_to_one_file(self):
        self.expect_error("two_outputs.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              <Output from="p" port="CT" file="${output}/same.vti"/>
              <Output from="p" port="Labels" file="${output}/same.vti"/>
            </AnatomeshPipeline>""", ":4: two outputs go to", "line 3")

    def test_property_set_twice(self):
        self.expect_error("twice.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource">
                <Property name="Spacing" value="8 8 8"/>
                <Property name="Spacing" value="4 4 4"/>
              </Filter>
            </AnatomeshPipeline>""", ":4: property 'Spacing' of filter 'p' is set twice (first at line 3)")

    def test_port_that_does_not_exist(self):
        self.expect_error("port5.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              <Filter name="s" type="LabelSurface"><Input from="p" port="5"/></Filter>
              <Output from="s" file="${output}/s.vtp"/>
            </AnatomeshPipeline>""", ":3: filter 'p' (ThoraxPhantomSource) has 2 output port(s), so no port 5")

    def test_wrong_data_type_fails_the_filter(self):
        stderr = self.expect_error("wrong_type_input.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              <Filter name="t" type="Tetrahedralize"><Input from="p" port="Labels"/></Filter>
              <Output from="t" file="${output}/t.vtu"/>
            </AnatomeshPipeline>""", "filter 't' (Tetrahedralize) failed", "vtkPolyData")
        self.assertFalse(os.path.exists(os.path.join(TMP, "err_wrong_type_input.xml", "t.vtu")), stderr)

    def test_unknown_filter(self):
        self.expect_error("unknown_filter.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="a" type="NoSuchFilter"/>
            </AnatomeshPipeline>""", ":2: unknown filter type 'NoSuchFilter'", "ThoraxPhantomSource")

    def test_unknown_property(self):
        self.expect_error("unknown_property.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="a" type="ThoraxPhantomSource">
                <Property name="Spacingg" value="1 1 1"/>
              </Filter>
            </AnatomeshPipeline>""", ":3: filter 'a' (ThoraxPhantomSource) has no property 'Spacingg'")

    def test_wrong_type_count_boolean_and_range(self):
        self.expect_error("wrong_type.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="a" type="ThoraxPhantomSource">
                <Property name="Seed" value="three"/>
              </Filter>
            </AnatomeshPipeline>""", ":3:", "must be an integer, got 'three'")
        self.expect_error("wrong_count.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="a" type="ThoraxPhantomSource">
                <Property name="Spacing" value="1 1"/>
              </Filter>
            </AnatomeshPipeline>""", ":3:", "needs 3 value(s), got 2")
        self.expect_error("wrong_range.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="a" type="ThoraxPhantomSource">
                <Property name="NoiseStandardDeviation" value="-4"/>
              </Filter>
            </AnatomeshPipeline>""", ":3:", "must be >= 0")
        self.expect_error("wrong_bool.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="r" type="ImageReader">
                <Property name="FileName" value="x.nii"/>
                <Property name="ResampleIrregularSeries" value="2"/>
              </Filter>
            </AnatomeshPipeline>""", ":4:", "boolean")

    def test_missing_input_file_names_the_file(self):
        stderr = self.expect_error("missing_file.xml", """
            <AnatomeshPipeline version="1">
              <Variable name="input" default="/no/such/scan.nii.gz"/>
              <Variable name="output" default="x"/>
              <Filter name="r" type="ImageReader">
                <Property name="FileName" value="${input}"/>
              </Filter>
              <Filter name="w" type="ImageWriter">
                <Input from="r"/>
                <Property name="FileName" value="${output}/copy.nii.gz"/>
              </Filter>
            </AnatomeshPipeline>""", "/no/such/scan.nii.gz", "does not exist")
        self.assertFalse(os.path.exists(os.path.join(TMP, "err_missing_file.xml", "copy.nii.gz")))

    def test_cycle(self):
        self.expect_error("cycle.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="a" type="ImageWriter">
                <Input from="b"/>
                <Property name="FileName" value="a.nii"/>
              </Filter>
              <Filter name="b" type="MeditWriter">
                <Input from="a"/>
                <Property name="FileName" value="b.mesh"/>
              </Filter>
            </AnatomeshPipeline>""", "writer")

    def test_unknown_variable_and_undeclared_set(self):
        self.expect_error("unknown_var.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="a" type="ThoraxPhantomSource">
                <Property name="Seed" value="${seed}"/>
              </Filter>
            </AnatomeshPipeline>""", ":3: unknown variable ${seed}")
        # A command-line mistake: exit status 2.
        path = pipeline_file("undeclared_set.xml", """
            <AnatomeshPipeline version="1">
              <Variable name="output" default="x"/>
            </AnatomeshPipeline>""")
        code, _, stderr = run("run", path, "--set", "bogus=1")
        self.assertEqual(code, 2, stderr)
        self.assertIn("--set names variables the pipeline does not declare: bogus", stderr)
        self.assertNotIn("Traceback", stderr)

    def test_defaults_that_follow_other_variables(self):
        # $(...) computes a default from the variables above it; --set replaces it, and what follows it.
        from anatomesh.pipeline import Pipeline
        path = pipeline_file("arithmetic.xml", """
            <AnatomeshPipeline version="1">
              <Variable name="spacing" default="1"/>
              <Variable name="tolerance" default="$(0.5 * ${spacing})"/>
              <Variable name="deviation" default="$(0.5 * ${tolerance})"/>
              <Variable name="size" default="$(max(4, 4 * ${spacing}) - (1 - 1))"/>
            </AnatomeshPipeline>""")
        self.assertEqual({k: Pipeline(path).variables[k] for k in ("tolerance", "deviation", "size")},
                         {"tolerance": "0.5", "deviation": "0.25", "size": "4"})
        given = Pipeline(path, {"spacing": "3"}).variables
        self.assertEqual((given["tolerance"], given["deviation"], given["size"]), ("1.5", "0.75", "12"))
        self.assertEqual(Pipeline(path, {"spacing": "3", "tolerance": "2"}).variables["deviation"], "1")
        # The main job's sizes follow its spacing unless set.
        job = Pipeline(os.path.join(SOURCE, "Examples", "Pipelines", "thorax.xml"), {"spacing": "3"}).variables
        self.assertEqual((job["tolerance"], job["deviation"], job["size"]), ("1.5", "0.75", "12"))
        for text, words in (("$(2 ** 8)", "only numbers"), ("$(1 / 0)", "division by zero"),
                            ("$(__import__('os'))", "only numbers"), ("$(1 +)", "cannot compute")):
            self.expect_error("arithmetic_bad.xml", """
                <AnatomeshPipeline version="1">
                  <Variable name="x" default="%s"/>
                </AnatomeshPipeline>""" % text, ":2: cannot compute", words)

    def test_version(self):
        code, stdout, _ = run("--version")
        self.assertEqual(code, 0)
        self.assertRegex(stdout, r"^anatomesh \d+\.\d+\.\d+ \(VTK 9\.")

    def test_malformed_xml_and_version(self):
        self.expect_error("malformed.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="a" type="ThoraxPhantomSource">
            </AnatomeshPipeline>""", ":3: malformed XML")
        self.expect_error("version.xml", """
            <AnatomeshPipeline version="7">
            </AnatomeshPipeline>""", ":1: unsupported pipeline format version")

    def test_missing_pipeline_file(self):
        code, _, stderr = run("run", "/no/such/pipeline.xml")
        self.assertEqual(code, 1)
        self.assertIn("/no/such/pipeline.xml: cannot read the pipeline file", stderr)


if __name__ == "__main__":
    unittest.main()
