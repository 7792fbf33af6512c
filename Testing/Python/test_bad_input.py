"""Bad input through the ``anatomesh`` command: corrupt and truncated scans and meshes, data a
filter cannot use, pipeline mistakes and write errors (a full disk, a file size limit, a read-only
folder). Every case asserts the exit status, the message's key words, no Python traceback, and
that no file appears at the output's final path (nor a temporary one beside it)."""
import gzip
import os
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import textwrap
import unittest

SOURCE = os.path.abspath(os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")))
TMP = os.environ.get("ANATOMESH_TEST_TMP", tempfile.gettempdir())
CLI = [sys.executable, os.path.join(SOURCE, "Wrapping", "anatomesh")]
ROOT = os.path.join(TMP, "bad_input")

# A 2-tetrahedron Medit mesh, as MeditWriter writes it.
MEDIT = """MeshVersionFormatted 2
Dimension 3
Vertices
5
0 0 0 0
1 0 0 0
0 1 0 0
0 0 1 0
1 1 1 0
Tetrahedra
2
1 2 3 4 1
2 3 4 5 2
End
"""


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)
    return path


def read(path):
    with open(path, "rb") as f:
        return f.read()


def patched(data, offset, fmt, *values):
    b = bytearray(data)
    struct.pack_into(fmt, b, offset, *values)
    return bytes(b)


def reader_pipeline(scan):
    return """
        <AnatomeshPipeline version="1">
          <Filter name="r" type="ImageReader"><Property name="FileName" value="%s"/></Filter>
          <Filter name="w" type="ImageWriter">
            <Input from="r"/><Property name="FileName" value="${output}/copy.nii.gz"/>
          </Filter>
          <Output from="r" file="${output}/copy.vti"/>
        </AnatomeshPipeline>""" % scan


def medit_pipeline(mesh):
    return """
        <AnatomeshPipeline version="1">
          <Filter name="r" type="MeditReader"><Property name="FileName" value="%s"/></Filter>
          <Filter name="q" type="MeshQuality"><Input from="r"/></Filter>
          <Output from="q" file="${output}/copy.vtu"/>
        </AnatomeshPipeline>""" % mesh


class BadInput(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(ROOT, ignore_errors=True)
        os.makedirs(ROOT)
        # The good files every bad one starts from: the phantom's labels at 8 mm in each format.
        writers = "".join(
            '<Filter name="w%d" type="ImageWriter"><Input from="p" port="Labels"/>'
            '<Property name="FileName" value="${output}/%s"/><Property name="UseCompression" value="%d"/></Filter>'
            % (i, name, compress) for i, (name, compress) in enumerate((
                ("labels.nii", 0), ("labels.nii.gz", 1), ("labels.nrrd", 0), ("labels_z.nrrd", 1),
                ("labels.mha", 0), ("labels_z.mha", 1), ("labels.mhd", 0))))
        src = cls.pipeline("good.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              %s
              <Output from="p" port="CT" file="${output}/ct.vti"/>
            </AnatomeshPipeline>""" % writers)
        code, _, stderr = cls.run_cli("run", src, "--quiet", "--output", os.path.join(ROOT, "good"))
        assert code == 0, stderr
        cls.good = {n: read(os.path.join(ROOT, "good", n)) for n in os.listdir(os.path.join(ROOT, "good"))}

    # -- helpers ---------------------------------------------------------------------------------
    @staticmethod
    def run_cli(*args, limit=None):
        def preexec():
            if limit:
                signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
                resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
        p = subprocess.run(CLI + list(args), capture_output=True, text=True, timeout=600,
                           preexec_fn=preexec if limit else None)
        return p.returncode, p.stdout, p.stderr

    @staticmethod
    def pipeline(name, body):
        return write(os.path.join(ROOT, name), textwrap.dedent(body).lstrip())

    def expect(self, name, body, *words, code=1, absent=(), args=(), limit=None, output=None):
        """Run a pipeline; assert the exit status, the words, no traceback and no file at 'absent'
        (names in the output folder) nor any temporary file there."""
        path = self.pipeline(name + ".xml", body)
        out = output or os.path.join(ROOT, "out_" + name)
        got, _, stderr = self.run_cli("run", path, "--quiet", "--output", out, *args, limit=limit)
        self.assertEqual(got, code, "%s: exit %d\n%s" % (name, got, stderr))
        for word in words:
            self.assertIn(word, stderr, name)
        self.assertNotIn("Traceback", stderr, name)
        for a in absent:
            self.assertFalse(os.path.exists(os.path.join(out, a)), "%s: %s was written" % (name, a))
        if os.path.isdir(out):
            temporaries = [f for f in os.listdir(out) if ".tmp" in f]
            self.assertEqual(temporaries, [], name)
        return stderr

    def bad_scan(self, name, data, *words, ext=".nii"):
        scan = write(os.path.join(ROOT, "scans", name + ext), data)
        return self.expect("scan_" + name, reader_pipeline(scan), os.path.basename(scan), *words,
                           absent=("copy.nii.gz", "copy.vti"))

    # -- readers: NIfTI --------------------------------------------------------------------------
    def test_nifti(self):
        nii, gz = self.good["labels.nii"], self.good["labels.nii.gz"]
        cases = [
            ("gz_cut_half", gz[:len(gz) // 2], "truncated", ".nii.gz"),
            ("gz_cut_1000", gz[:1000], "truncated", ".nii.gz"),
            ("raw_cut_half", nii[:len(nii) // 2], "truncated", ".nii"),
            ("gz_corrupt_deflate", gz[:200] + bytes(b ^ 0x5A for b in gz[200:400]) + gz[400:], "corrupt", ".nii.gz"),
            ("gz_bad_crc", gz[:-8] + bytes(b ^ 0xFF for b in gz[-8:-4]) + gz[-4:], "corrupt", ".nii.gz"),
            ("huge_dims", patched(nii, 42, "<3h", 30000, 30000, 30000), "truncated", ".nii"),
            ("offset_past_end", patched(nii, 108, "<f", 1.0e7), "past its end", ".nii"),
            ("nan_sform", patched(patched(nii, 254, "<h", 1), 280, "<f", float("nan")), "sform", ".nii"),
            ("degenerate_sform", patched(patched(nii, 254, "<h", 1), 280, "<12f", *([0.0] * 12)), "degenerate", ".nii"),
            ("nan_qform", patched(patched(nii, 252, "<h", 1), 256, "<f", float("nan")), "quatern_b", ".nii"),
            ("zero_voxel_size", patched(nii, 80, "<f", 0.0), "pixdim[1]", ".nii"),
            ("bad_magic", patched(nii, 344, "4s", b"xyz\0"), "magic", ".nii"),
            ("short_header", nii[:100], "shorter than a NIfTI header", ".nii"),
            ("zero_bitpix", patched(nii, 72, "<h", 0), "bitpix", ".nii"),
            ("empty", b"", "shorter than a NIfTI header", ".nii"),
            ("gzip_of_nothing", gzip.compress(b""), "shorter than a NIfTI header", ".nii.gz"),
            ("gzip_of_a_short_header", gzip.compress(nii[:300]), "shorter than a NIfTI header", ".nii.gz"),
        ]
        for name, data, word, ext in cases:
            with self.subTest(name):
                self.bad_scan("nifti_" + name, data, word, ext=ext)

    # -- readers: NRRD, MetaImage, others --------------------------------------------------------
    def test_nrrd(self):
        raw = self.good["labels.nrrd"]
        header, _, voxels = raw.partition(b"\n\n")
        text = header.decode()

        def with_field(key, value):
            lines = [l for l in text.splitlines() if not l.startswith(key + ":")]
            return ("\n".join(lines + ["%s: %s" % (key, value)]) + "\n\n").encode() + voxels

        folder = os.path.join(ROOT, "scans", "a_folder")
        os.makedirs(folder, exist_ok=True)
        cases = [
            ("nan_spacing", with_field("spacings", "nan 8 8").replace(b"space directions", b"#"), "spacings"),
            ("truncated", raw[:len(raw) - 100], "truncated"),
            ("gzip_cut", self.good["labels_z.nrrd"][:len(self.good["labels_z.nrrd"]) - 40], "truncated"),
            ("huge_sizes", with_field("sizes", "100000 100000 100000"), "truncated"),
            ("zero_direction", with_field("space directions", "(0,0,0) (0,8,0) (0,0,8)"), "space directions"),
            ("missing_data_file", with_field("data file", "no_such.raw"), "does not exist"),
            ("data_file_a_folder", with_field("data file", folder), "not a regular file"),
            ("sizes_count", with_field("sizes", "4 4"), "'sizes'"),
        ]
        for name, data, word in cases:
            with self.subTest(name):
                self.bad_scan("nrrd_" + name, data, word, ext=".nrrd")

    def test_metaimage_and_others(self):
        mha = self.good["labels.mha"]
        text, _, voxels = mha.partition(b"ElementDataFile = LOCAL\n")

        def with_field(key, value):
            lines = [l for l in text.decode().splitlines() if not l.startswith(key + " ")]
            return ("\n".join(lines + ["%s = %s" % (key, value), "ElementDataFile = LOCAL"]) + "\n").encode() + voxels

        mhd = self.good["labels.mhd"].decode()
        cases = [
            ("mha_truncated", mha[:len(mha) - 100], "truncated", ".mha"),
            ("mha_nan_spacing", with_field("ElementSpacing", "nan 8 8"), "ElementSpacing", ".mha"),
            ("mha_negative_size", with_field("DimSize", "-5 4 4"), "DimSize", ".mha"),
            ("mha_degenerate_matrix", with_field("TransformMatrix", "1 0 0 1 0 0 0 0 1"), "TransformMatrix", ".mha"),
            ("mha_compressed_cut", self.good["labels_z.mha"][:-30], "compressed voxel data", ".mha"),
            ("mhd_missing_raw", mhd.replace("labels.raw", "no_such.raw").encode(), "does not exist", ".mhd"),
            ("not_an_image", b"hello, this is text\n" * 40, "", ".nii"),
            ("unknown_extension", b"\0" * 400, "not a NIfTI, NRRD, MetaImage or DICOM", ".xyz"),
        ]
        for name, data, word, ext in cases:
            with self.subTest(name):
                self.bad_scan(name, data, word, ext=ext)
        with self.subTest("missing_file"):
            self.expect("scan_missing", reader_pipeline("/no/such/scan.nii.gz"), "/no/such/scan.nii.gz",
                        "does not exist", absent=("copy.nii.gz", "copy.vti"))
        with self.subTest("folder_without_dicom"):
            empty = os.path.join(ROOT, "scans", "empty_folder")
            os.makedirs(empty, exist_ok=True)
            self.expect("scan_empty_folder", reader_pipeline(empty), "empty_folder", absent=("copy.nii.gz",))

    # -- readers: Medit ---------------------------------------------------------------------------
    def test_medit(self):
        cases = [
            ("cut_before_tetrahedra", MEDIT[:MEDIT.index("Tetrahedra")], "End"),
            ("binary_garbage", bytes(range(256)) * 8, "bad_medit_binary_garbage.mesh"),
            ("vertex_out_of_range", MEDIT.replace("2 3 4 5 2", "2 3 4 9 2"), "uses vertex 9"),
            ("huge_count_short_file", MEDIT.replace("Vertices\n5", "Vertices\n1999999999"), "line"),
            ("unknown_section", MEDIT.replace("Tetrahedra", "Pyramids"), "Pyramids"),
            ("not_a_number", MEDIT.replace("1 1 1 0", "1 x 1 0"), "vertex coordinate"),
            ("second_vertex_section", MEDIT.replace("End", "Vertices\n0\nEnd"), "a second Vertices section"),
        ]
        for name, data, word in cases:
            with self.subTest(name):
                mesh = write(os.path.join(ROOT, "meshes", "bad_medit_%s.mesh" % name), data)
                self.expect("medit_" + name, medit_pipeline(mesh), os.path.basename(mesh), word, absent=("copy.vtu",))
        with self.subTest("solution_wrong_count"):
            mesh = write(os.path.join(ROOT, "meshes", "with_sol.mesh"), MEDIT)
            write(os.path.join(ROOT, "meshes", "with_sol.sol"), "MeshVersionFormatted 2\nDimension 3\n"
                  "SolAtVertices\n3\n1 1\n0\n1\n2\nEnd\n")
            self.expect("medit_sol", medit_pipeline(mesh), "SolAtVertices has 3 values for 5 vertices",
                        absent=("copy.vtu",))

    # -- filters ----------------------------------------------------------------------------------
    def test_filters(self):
        cases = [
            ("tetrahedralize_an_image", """
                <Filter name="t" type="Tetrahedralize"><Input from="p" port="Labels"/></Filter>
                <Output from="t" file="${output}/t.vtu"/>""", ["filter 't' (Tetrahedralize) failed", "vtkPolyData"],
             ["t.vtu"]),
            ("surface_of_an_empty_map", """
                <Filter name="c" type="IntensityClassifier"><Input from="p" port="CT"/>
                  <Property name="Ranges" value="5000 6000 1"/></Filter>
                <Filter name="s" type="LabelSurface"><Input from="c"/></Filter>
                <Output from="s" file="${output}/s.vtp"/>""", ["no voxel with a label other than the background"],
             ["s.vtp"]),
            ("remesh_an_image", """
                <Filter name="m" type="MetricRemeshing"><Input from="p" port="Labels"/></Filter>
                <Output from="m" file="${output}/m.vtp"/>""", ["filter 'm' (MetricRemeshing) failed"], ["m.vtp"]),
            ("quality_of_an_image", """
                <Filter name="q" type="MeshQuality"><Input from="p" port="Labels"/></Filter>
                <Output from="q" file="${output}/q.vtu"/>""", ["filter 'q' (MeshQuality) failed"], ["q.vtu"]),
            ("seed_outside_the_image", """
                <Filter name="s" type="SnakeSegmentation"><Input from="p" port="CT"/>
                  <Property name="Seeds" value="5000 5000 5000 1"/></Filter>
                <Output from="s" file="${output}/s.vti"/>""", ["outside"], ["s.vti"]),
        ]
        for name, body, words, absent in cases:
            with self.subTest(name):
                self.expect("filter_" + name, """
                    <AnatomeshPipeline version="1">
                      <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
                      %s
                    </AnatomeshPipeline>""" % body, *words, absent=absent)

    def test_non_finite_voxels(self):
        # A NIfTI float image with NaN and infinite voxels, classified and segmented.
        nii = self.good["labels.nii"]
        offset = int(struct.unpack("<f", nii[108:112])[0])
        dims = struct.unpack("<3h", nii[42:48])
        count = dims[0] * dims[1] * dims[2]
        header = patched(patched(nii[:offset], 70, "<h", 16), 72, "<h", 32)  # datatype FLOAT32, bitpix 32
        for name, value, word in (("nan", float("nan"), "NaN"), ("inf", float("inf"), "infinite")):
            voxels = [0.0] * count
            voxels[count // 2] = value
            scan = write(os.path.join(ROOT, "scans", "float_%s.nii" % name),
                         header + struct.pack("<%df" % count, *voxels))
            for kind, body in (("classify", """
                    <Filter name="c" type="IntensityClassifier"><Input from="r"/></Filter>
                    <Output from="c" file="${output}/c.vti"/>"""), ("snake", """
                    <Filter name="c" type="SnakeSegmentation"><Input from="r"/>
                      <Property name="Seeds" value="0 0 0 1"/></Filter>
                    <Output from="c" file="${output}/c.vti"/>""")):
                with self.subTest(name + "_" + kind):
                    self.expect("nonfinite_%s_%s" % (name, kind), """
                        <AnatomeshPipeline version="1">
                          <Filter name="r" type="ImageReader"><Property name="FileName" value="%s"/></Filter>
                          %s
                        </AnatomeshPipeline>""" % (scan, body), word, absent=("c.vti",))

    # -- the pipeline runner -----------------------------------------------------------------------
    def test_runner(self):
        scan = write(os.path.join(ROOT, "runner", "input.nii.gz"), self.good["labels.nii.gz"])
        link = os.path.join(ROOT, "runner", "hardlink.nii.gz")
        if not os.path.exists(link):
            os.link(scan, link)
        phantom = '<Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>'
        cases = [
            ("output_over_input", """
                <Filter name="r" type="ImageReader"><Property name="FileName" value="%s"/></Filter>
                <Filter name="w" type="ImageWriter"><Input from="r"/>
                  <Property name="FileName" value="%s"/></Filter>""" % (scan, scan), ["would overwrite the input"]),
            ("output_over_input_by_inode", """
                <Filter name="r" type="ImageReader"><Property name="FileName" value="%s"/></Filter>
                <Output from="r" file="%s"/>""" % (scan, link), ["would overwrite the input"]),
            ("two_outputs_one_file", phantom + """
                <Output from="p" port="CT" file="${output}/x.vti"/>
                <Output from="p" port="Labels" file="${output}/x.vti"/>""", ["two outputs go to"]),
            ("property_twice", """
                <Filter name="p" type="ThoraxPhantomSource">
                  <Property name="Spacing" value="8 8 8"/><Property name="Spacing" value="8 8 8"/></Filter>""",
             ["is set twice"]),
            ("port_out_of_range", phantom + '<Output from="p" port="5" file="${output}/x.vti"/>', ["no port 5"]),
            ("port_not_a_number", phantom + '<Output from="p" port="x1" file="${output}/x.vti"/>',
             ["no output port 'x1'"]),
            ("port_superscript_digit", phantom + '<Output from="p" port="\u00b2" file="${output}/x.vti"/>',
             ["no output port"]),
            ("integer_out_of_range", """
                <Filter name="p" type="ThoraxPhantomSource"><Property name="Seed" value="1e30"/></Filter>""",
             ["must be an integer"]),
            ("nan_property", """
                <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="nan 8 8"/></Filter>""",
             ["is NaN"]),
            ("infinite_property", """
                <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="inf 8 8"/></Filter>""",
             ["must be finite"]),
            ("extension_does_not_fit", phantom + '<Output from="p" port="CT" file="${output}/x.vtu"/>',
             ["holds a vtkUnstructuredGrid", "use .vti"]),
            ("unknown_extension", phantom + '<Output from="p" port="CT" file="${output}/x.xyz"/>',
             ["unknown output extension"]),
            ("writer_without_file_name", phantom + """
                <Filter name="w" type="ImageWriter"><Input from="p" port="Labels"/></Filter>""", ["FileName"]),
            ("input_from_a_writer", phantom + """
                <Filter name="w" type="ImageWriter"><Input from="p" port="Labels"/>
                  <Property name="FileName" value="${output}/w.nii"/></Filter>
                <Filter name="s" type="LabelSurface"><Input from="w"/></Filter>""", ["comes from writer"]),
            ("input_from_nowhere", """
                <Filter name="s" type="LabelSurface"><Input from="nowhere"/></Filter>""",
             ["not a filter of this pipeline"]),
            ("unconnected_input", """<Filter name="s" type="LabelSurface"/>""", ["needs its input"]),
            ("external_entity", None, ["malformed XML"]),
            ("binary_garbage", None, ["malformed XML"]),
        ]
        for name, body, words in cases:
            with self.subTest(name):
                if name == "external_entity":
                    text = ('<?xml version="1.0"?><!DOCTYPE p [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
                            '<AnatomeshPipeline version="1"><Variable name="v" default="&x;"/></AnatomeshPipeline>')
                elif name == "binary_garbage":
                    text = "".join(chr(c) for c in range(1, 256)) * 4
                else:
                    text = '<AnatomeshPipeline version="1">%s</AnatomeshPipeline>' % body
                self.expect("runner_" + name, text, *words, absent=("x.vti", "x.vtu", "x.xyz", "w.nii"))
        self.assertEqual(read(scan), self.good["labels.nii.gz"])

    def test_long_chain_and_command_line(self):
        with self.subTest("cycle_through_1500_filters"):
            # Listed from its end, so the cycle check walks 1500 filters deep (Python's own recursion
            # stopped at 1000).
            chain = ['<Filter name="f1" type="SurfaceSmoothing"><Input from="f1499"/></Filter>']
            chain += ['<Filter name="f%d" type="SurfaceSmoothing"><Input from="f%d"/></Filter>' % (i, i - 1)
                      for i in range(2, 1500)]
            self.expect("chain", '<AnatomeshPipeline version="1">%s</AnatomeshPipeline>' % "".join(reversed(chain)),
                        "the pipeline has a cycle: f1499 -> f1498")
        with self.subTest("output_folder_is_a_file"):
            blocker = write(os.path.join(ROOT, "a_file"), "x")
            self.expect("output_is_file", """
                <AnatomeshPipeline version="1">
                  <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
                  <Output from="p" port="CT" file="${output}/x.vti"/>
                </AnatomeshPipeline>""", "a_file", output=blocker)
        with self.subTest("unknown_set_variable"):
            self.expect("unknown_set", '<AnatomeshPipeline version="1"/>', "bogus", code=2, args=("--set", "bogus=1"))
        with self.subTest("set_without_equals"):
            self.expect("set_no_equals", '<AnatomeshPipeline version="1"/>', "--set", code=2, args=("--set", "bogus"))

    # -- writers -----------------------------------------------------------------------------------
    WRITERS = """
        <AnatomeshPipeline version="1">
          <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="3 3 3"/></Filter>
          <Filter name="t" type="LabelMapTetrahedralize"><Input from="p" port="Labels"/>
            <Property name="CellSize" value="12"/><Property name="FacetSize" value="12"/>
            <Property name="FacetDistance" value="3"/></Filter>
          %s
        </AnatomeshPipeline>"""
    TARGETS = {
        "nifti": ('<Filter name="w" type="ImageWriter"><Input from="p" port="CT"/>'
                  '<Property name="FileName" value="${output}/out.nii.gz"/></Filter>', "out.nii.gz"),
        "vti": ('<Output from="p" port="CT" file="${output}/out.vti"/>', "out.vti"),
        "medit": ('<Filter name="w" type="MeditWriter"><Input from="t"/>'
                  '<Property name="FileName" value="${output}/out.mesh"/></Filter>', "out.mesh"),
        "gmsh": ('<Filter name="w" type="GmshWriter"><Input from="t"/>'
                 '<Property name="FileName" value="${output}/out.msh"/></Filter>', "out.msh"),
        "metaimage": ('<Filter name="w" type="ImageWriter"><Input from="p" port="CT"/>'
                      '<Property name="FileName" value="${output}/out.mha"/></Filter>', "out.mha"),
        "metaimage_detached": ('<Filter name="w" type="ImageWriter"><Input from="p" port="CT"/>'
                               '<Property name="FileName" value="${output}/out.mhd"/>'
                               '<Property name="UseCompression" value="0"/></Filter>', "out.mhd"),
        "xdmf": ('<Filter name="w" type="XdmfWriter"><Input from="t"/>'
                 '<Property name="FileName" value="${output}/out.xdmf"/></Filter>', "out.xdmf"),
        "opencarp": ('<Filter name="w" type="OpenCARPWriter"><Input from="t"/>'
                     '<Property name="FileName" value="${output}/out.pts"/></Filter>', "out.pts"),
        "nrrd": ('<Filter name="w" type="ImageWriter"><Input from="p" port="CT"/>'
                 '<Property name="FileName" value="${output}/out.nrrd"/></Filter>', "out.nrrd"),
        "label_map_and_tables": ('<Filter name="w" type="ImageWriter"><Input from="p" port="Labels"/>'
                                 '<Property name="FileName" value="${output}/out.nii"/>'
                                 '<Property name="UseCompression" value="0"/></Filter>', "out.nii"),
        "vtp": ('<Filter name="s" type="LabelSurface"><Input from="p" port="Labels"/></Filter>'
                '<Output from="s" file="${output}/out.vtp"/>', "out.vtp"),
        "vtu": ('<Output from="t" file="${output}/out.vtu"/>', "out.vtu"),
        "csv": ('<Filter name="q" type="MeshQuality"><Input from="t"/></Filter>'
                '<Output from="q" port="Table" file="${output}/out.csv"/>', "out.csv"),
        "pvd_frames": ('<Filter name="h" type="FitzHughNagumoSolver"><Input from="t"/>'
                       '<Property name="HeartRegions" value="5"/><Property name="StimulusCenter" value="61 -51.5 -25"/>'
                       '<Property name="EndTime" value="20"/><Property name="OutputInterval" value="5"/></Filter>'
                       '<Output from="h" file="${output}/out.pvd"/>', "out.pvd"),
    }
    # A limit under each target's size (a quality table is a few hundred bytes, a heart frame a few kB).
    LIMITS = {"csv": 200, "pvd_frames": 2048}

    def test_write_errors_under_a_file_size_limit(self):
        # Every format, over an old file at its path: the run fails naming it, the old file stays as it
        # was (never half a new one), and no temporary is left.
        for kind, (body, target) in self.TARGETS.items():
            with self.subTest(kind):
                out = os.path.join(ROOT, "out_fsize_" + kind)
                write(os.path.join(out, target), b"the old file")
                self.expect("fsize_" + kind, self.WRITERS % body, target, limit=self.LIMITS.get(kind, 64 * 1024),
                            output=out)
                self.assertEqual(read(os.path.join(out, target)), b"the old file", kind)

    def mounted(self, options):
        folder = tempfile.mkdtemp(prefix="anatomesh-mount-", dir=ROOT)
        if os.geteuid() != 0 or subprocess.run(["mount", "-t", "tmpfs", "-o", options, "tmpfs", folder],
                                               capture_output=True).returncode != 0:
            self.skipTest("mounting a tmpfs needs root and the right to mount here")
        self.addCleanup(subprocess.run, ["umount", "-l", folder], capture_output=True)
        return folder

    def test_full_disk(self):
        folder = self.mounted("size=256k")
        for kind, (body, target) in self.TARGETS.items():
            with self.subTest(kind):
                filler = os.path.join(folder, "filler")
                if kind == "csv":  # a small file: the disk is full before it is written
                    os.makedirs(os.path.join(folder, kind), exist_ok=True)
                    try:
                        with open(filler, "wb") as f:
                            while True:
                                f.write(b"x" * 4096)
                                f.flush()
                    except OSError:
                        pass
                try:
                    self.expect("full_" + kind, self.WRITERS % body, target, absent=(target,),
                                output=os.path.join(folder, kind))
                finally:
                    if os.path.exists(filler):
                        os.remove(filler)
        self.assertEqual([f for root, _, files in os.walk(folder) for f in files if ".tmp" in f], [])

    def test_read_only_folder(self):
        folder = self.mounted("size=1m")
        os.makedirs(os.path.join(folder, "out"))
        subprocess.run(["mount", "-o", "remount,ro", folder], check=True)
        for kind, (body, target) in self.TARGETS.items():
            with self.subTest(kind):
                # The run stops before any filter: the output folder is named with the system's words.
                self.expect("readonly_" + kind, self.WRITERS % body, os.path.join(folder, "out"),
                            "Read-only file system", absent=(target,), output=os.path.join(folder, "out"))


if __name__ == "__main__":
    unittest.main()
