"""Faults no user should meet, and what the command does about them: runs killed while they write, batch
manifests and run markers fuzzed, readers given files that would block them or that they would read
silently wrong, messages cut or unnamed. Beside test_bad_input (corrupt inputs, and every writer under a file
size limit, on a full disk and in a read-only folder). Every case asserts no traceback, and no file at a final
path that differs from what its writer meant: old or new, never half."""
import codecs
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest

from test_bad_input import read, write  # the same helpers, one copy

SOURCE = os.path.abspath(os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")))
TMP = os.environ.get("ANATOMESH_TEST_TMP", tempfile.gettempdir())
SHARED = os.environ.get("ANATOMESH_SHARED_DATA", os.path.join(SOURCE, "..", "shared", "data"))
CLI = [sys.executable, os.path.join(SOURCE, "Wrapping", "anatomesh")]
ROOT = os.path.join(TMP, "faults")

# A small pipeline writing a label map, a mesh in three formats and a table: what the kill test interrupts.
WRITING = """
<AnatomeshPipeline version="1">
  <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="3 3 3"/></Filter>
  <Filter name="t" type="LabelMapTetrahedralize"><Input from="p" port="Labels"/>
    <Property name="CellSize" value="12"/><Property name="FacetSize" value="12"/>
    <Property name="FacetDistance" value="3"/></Filter>
  <Filter name="q" type="MeshQuality"><Input from="t"/></Filter>
  <Filter name="wi" type="ImageWriter"><Input from="p" port="CT"/>
    <Property name="FileName" value="${output}/ct.nii.gz"/></Filter>
  <Filter name="wm" type="MeditWriter"><Input from="t"/><Property name="FileName" value="${output}/mesh.mesh"/></Filter>
  <Filter name="wg" type="GmshWriter"><Input from="t"/><Property name="FileName" value="${output}/mesh.msh"/></Filter>
  <Filter name="wx" type="XdmfWriter"><Input from="t"/><Property name="FileName" value="${output}/mesh.xdmf"/></Filter>
  <Filter name="wc" type="OpenCARPWriter"><Input from="t"/><Property name="FileName" value="${output}/mesh.pts"/>
  </Filter>
  <Filter name="wa" type="ImageWriter"><Input from="p" port="Labels"/>
    <Property name="FileName" value="${output}/labels.mha"/></Filter>
  <Output from="q" port="Mesh" file="${output}/mesh.vtu"/>
  <Output from="q" port="Table" file="${output}/quality.csv"/>
</AnatomeshPipeline>
"""
TARGETS = ("ct.nii.gz", "labels.mha", "mesh.mesh", "mesh.msh", "mesh.xdmf", "mesh_facets.xdmf", "mesh.h5",
           "mesh_facets.h5", "mesh.pts", "mesh.elem", "mesh.vtu", "quality.csv")

# A quick case for the batch: the phantom's labels at 10 mm.
SMALL = """
<AnatomeshPipeline version="1">
  <Variable name="spacing" default="10"/>
  <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="${spacing} ${spacing} ${spacing}"/>
  </Filter>
  <Filter name="w" type="ImageWriter"><Input from="p" port="Labels"/>
    <Property name="FileName" value="${output}/labels.nii.gz"/></Filter>
</AnatomeshPipeline>
"""


def reading(path, kind="ImageReader"):
    """A pipeline that reads 'path' with the reader 'kind' and writes what it read."""
    return """
        <AnatomeshPipeline version="1">
          <Filter name="r" type="%s"><Property name="FileName" value="%s"/></Filter>
          <Output from="r" file="${output}/x.%s"/>
        </AnatomeshPipeline>""" % (kind, path, "vti" if kind == "ImageReader" else "vtu")


def run(*args, timeout=600):
    p = subprocess.run(CLI + list(args), capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def temporaries(folder):
    return sorted(os.path.join(r, f) for r, dirs, files in os.walk(folder) for f in files + dirs if ".tmp" in f)


class Faults(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        shutil.rmtree(ROOT, ignore_errors=True)
        os.makedirs(ROOT)

    def pipeline(self, name, body):
        return write(os.path.join(ROOT, name), textwrap.dedent(body).lstrip())

    def refused(self, name, body, *words, code=1):
        """Runs a pipeline that must be refused: the exit status, the words, no traceback, within a minute."""
        code_got, _, stderr = run("run", self.pipeline(name + ".xml", body), "--quiet", "--output",
                                  os.path.join(ROOT, "out_" + name), timeout=120)
        self.assertEqual(code_got, code, "%s: exit %d\n%s" % (name, code_got, stderr))
        for word in words:
            self.assertIn(word, stderr, name)
        self.assertNotIn("Traceback", stderr, name)
        return stderr

    # -- writes interrupted ------------------------------------------------------------------------------
    def test_killed_while_writing_leaves_the_old_file_or_the_new_one(self):
        # The same run gives the same bytes: what a killed run leaves at each final path is the old file or
        # the complete new one, whenever the kill comes.
        path = self.pipeline("writing.xml", WRITING)
        reference = os.path.join(ROOT, "writing_reference")
        code, _, stderr = run("run", path, "--quiet", "--output", reference)
        self.assertEqual(code, 0, stderr)
        new = {t: read(os.path.join(reference, t)) for t in TARGETS}
        start = time.time()
        code, _, _ = run("run", path, "--quiet", "--output", os.path.join(ROOT, "writing_timed"))
        seconds = time.time() - start
        out = os.path.join(ROOT, "writing_killed")
        seen = set()
        for k, fraction in enumerate((0.3, 0.5, 0.65, 0.8, 0.9, 0.97)):
            for number in (signal.SIGKILL, signal.SIGTERM):
                with self.subTest(at=fraction, signal=number):
                    for t in TARGETS:
                        write(os.path.join(out, t), b"the old file")
                    process = subprocess.Popen(CLI + ["run", path, "--quiet", "--output", out],
                                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                                               start_new_session=True)
                    time.sleep(seconds * fraction)
                    try:
                        os.killpg(process.pid, number)
                    except ProcessLookupError:
                        pass
                    _, stderr = process.communicate(timeout=120)
                    self.assertNotIn("Traceback", stderr)
                    for t in TARGETS:
                        got = read(os.path.join(out, t))
                        self.assertIn(got, (b"the old file", new[t]), "%s after a kill at %.0f %%" % (t, 100 * fraction))
                        seen.add((t, got == new[t]))
        # The kills came both before and after some files were replaced.
        self.assertTrue(any(replaced for _, replaced in seen) and any(not replaced for _, replaced in seen), seen)
        # A later run removes what the killed ones left (their processes are gone).
        code, _, stderr = run("run", path, "--quiet", "--output", out)
        self.assertEqual(code, 0, stderr)
        self.assertEqual(temporaries(out), [])
        for t in TARGETS:
            self.assertEqual(read(os.path.join(out, t)), new[t], t)

    def test_text_files_keep_the_old_file_under_a_size_limit(self):
        # The run marker, the report and the batch summary go through one atomic text writer.
        target = write(os.path.join(ROOT, "atomic", "marker.json"), "the old file")
        script = textwrap.dedent("""
            import resource, signal, sys
            from anatomesh import atomic
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (1000, 1000))
            try:
                atomic.write_text(sys.argv[1], "x" * 5000)
            except OSError as e:
                print("%s|%s" % (e.filename, e.strerror))
            """)
        p = subprocess.run([sys.executable, "-c", script, target], capture_output=True, text=True, timeout=60)
        self.assertEqual(p.stdout.strip(), "%s|File too large" % target, p.stderr)
        self.assertEqual(read(target), b"the old file")
        self.assertEqual(temporaries(os.path.dirname(target)), [])

    # -- batch manifests and run markers --------------------------------------------------------------------
    def test_manifest_fuzz(self):
        # Random manifests: names and output folders with '..', '/', absolute paths, repeats, nesting, empty
        # cells, byte-order marks in four encodings, CR LF, NUL bytes, stray quotes. Each is refused with a
        # ManifestError or a message, or gives folders inside --output, each its own.
        from anatomesh.batch import ManifestError, case_folders, read_manifest
        rng = random.Random(59)
        names = ["a", "b", "..", ".", "a/b", "/abs", "", "é", "x" * 300, "a\\b", " a ", "c", "a"]
        outputs = ["", "same", "same", "same/inner", "../up", "/tmp", "./a", "a/../../b", "deep/er", "é/ü"]
        encodings = [("utf-8", b""), ("utf-8", codecs.BOM_UTF8), ("utf-16-le", codecs.BOM_UTF16_LE),
                     ("utf-16-be", codecs.BOM_UTF16_BE), ("utf-32-le", codecs.BOM_UTF32_LE)]
        out = os.path.join(ROOT, "fuzz_out")
        counts = {"refused": 0, "accepted": 0}
        for trial in range(400):
            columns = rng.choice([["case", "spacing"], ["case", "spacing", "output"], ["spacing", "output"],
                                  ["spacing"], ["case", "colour"]])
            lines = [",".join(columns)]
            for _ in range(rng.randint(0, 4)):
                row = []
                for c in columns:
                    row.append(rng.choice(names) if c == "case" else rng.choice(outputs) if c == "output"
                               else rng.choice(["8", "10", "", '"9"', "x\x00y"]))
                lines.append(",".join(row))
            text = ("\r\n" if rng.random() < 0.3 else "\n").join(lines) + "\n"
            encoding, bom = rng.choice(encodings)
            path = write(os.path.join(ROOT, "fuzz", "m%d.csv" % trial), bom + text.encode(encoding))
            with self.subTest(trial=trial, text=text, encoding=encoding, bom=bool(bom)):
                try:
                    cases = read_manifest(path, {"spacing", "output"})
                except ManifestError as e:
                    self.assertIn(path, str(e))
                    counts["refused"] += 1
                    continue
                work = [(name, dict(values)) for name, values in cases]
                problem = case_folders(work, out)
                if problem:
                    counts["refused"] += 1
                    continue
                counts["accepted"] += 1
                real = [os.path.realpath(v["output"]) for _, v in work]
                root = os.path.realpath(out)
                for r in real:
                    self.assertTrue(r.startswith(root + os.sep), (r, text))
                for i, a in enumerate(real):
                    for b in real[i + 1:]:
                        self.assertFalse(a == b or a.startswith(b + os.sep) or b.startswith(a + os.sep), (a, b))
        self.assertGreater(counts["refused"], 50, counts)
        self.assertGreater(counts["accepted"], 50, counts)

    def test_manifest_encodings_and_folders_through_the_command(self):
        pipeline = self.pipeline("small.xml", SMALL)
        for encoding, bom in (("utf-8", codecs.BOM_UTF8), ("utf-16-le", codecs.BOM_UTF16_LE)):
            with self.subTest(encoding):
                manifest = write(os.path.join(ROOT, "bom_%s.csv" % encoding),
                                 bom + "case,spacing\r\nfirst,10\r\n".encode(encoding))
                out = os.path.join(ROOT, "bom_out_" + encoding)
                code, stdout, stderr = run("batch", pipeline, manifest, "--output", out)
                self.assertEqual(code, 0, stderr)
                self.assertTrue(os.path.isfile(os.path.join(out, "first", "labels.nii.gz")))
        with self.subTest("outside only when asked"):
            elsewhere = os.path.join(ROOT, "elsewhere")
            manifest = write(os.path.join(ROOT, "outside.csv"), "case,spacing,output\nfar,10,%s\n" % elsewhere)
            code, _, stderr = run("batch", pipeline, manifest, "--output", os.path.join(ROOT, "outside_out"))
            self.assertEqual(code, 2, stderr)
            self.assertIn("--outputs-anywhere", stderr)
            self.assertFalse(os.path.exists(elsewhere))
            code, _, stderr = run("batch", pipeline, manifest, "--output", os.path.join(ROOT, "outside_out"),
                                  "--outputs-anywhere")
            self.assertEqual(code, 0, stderr)
            self.assertTrue(os.path.isfile(os.path.join(elsewhere, "labels.nii.gz")))

    MARKERS = [b"[1, 2]", b'"complete"', b"{", b"\xff\xfe garbage", b"null", b"{}",
               b'{"status": "complete", "pipeline": 5, "variables": {}, "seconds": 1}',
               b'{"status": "complete", "pipeline": "p", "variables": [], "seconds": 1}',
               b'{"status": "complete", "pipeline": "p", "variables": {}, "seconds": "fast"}',
               b'{"status": "complete", "pipeline": "p", "variables": {}, "seconds": 1, "figures": {"a": 3}}',
               b'{"status": "complete", "pipeline": "p", "variables": {}, "seconds": 1, "files": "x"}',
               b'{"status": "complete", "pipeline": "p", "variables": {"a": 1}, "seconds": 1}',
               b'{"status": "done", "pipeline": "p", "variables": {}, "seconds": 1}',
               b'{"status": "complete", "pipeline": "p", "variables": {}, "seconds": NaN}',
               b'{"status": "complete", "pipeline": "p", "variables": {}, "seconds": 1e999}',
               b'{"status": "complete", "pipeline": "p", "variables": {}}']

    def test_marker_fuzz(self):
        from anatomesh import marker
        folder = os.path.join(ROOT, "marker_fuzz")
        rng = random.Random(58)
        good = {"status": "complete", "pipeline": "/p.xml", "variables": {"output": "x"}, "files": ["/x/a.vtu"],
                "seconds": 1.5, "stage_seconds": {"a": 0.1}, "figures": {"a.vtu": {"tetrahedra": 3}}, "warnings": []}
        values = [None, True, 0, -1, 1e308, "", "x", [], [1, "a"], {}, {"k": []}, {"k": {"j": 1}}]
        samples = list(self.MARKERS)
        for _ in range(300):
            record = dict(good)
            for key in rng.sample(sorted(good), rng.randint(1, 3)):
                if rng.random() < 0.2:
                    record.pop(key)
                else:
                    record[key] = rng.choice(values)
            samples.append(json.dumps(record).encode())
        warnings = []
        for data in samples:
            with self.subTest(data=data[:80]):
                write(marker.path(folder), data)
                got = marker.read(folder, warn=warnings.append)
                if got is not None:
                    self.assertIsNone(marker.malformed(got))
                    self.assertIsInstance(got["variables"], dict)
                else:
                    self.assertIn(marker.path(folder), warnings[-1])
        write(marker.path(folder), json.dumps(good))
        self.assertEqual(marker.read(folder), good)

    def test_resume_and_report_over_malformed_markers(self):
        pipeline = self.pipeline("small_resume.xml", SMALL)
        manifest = write(os.path.join(ROOT, "resume.csv"), "case,spacing\nfirst,10\n")
        out = os.path.join(ROOT, "resume_out")
        code, _, stderr = run("batch", pipeline, manifest, "--output", out)
        self.assertEqual(code, 0, stderr)
        marker_path = os.path.join(out, "first", "anatomesh-run.json")
        for data in self.MARKERS[:4] + self.MARKERS[8:10]:
            with self.subTest(data=data):
                write(marker_path, data)
                code, _, stderr = run("batch", pipeline, manifest, "--output", out, "--resume")
                self.assertEqual(code, 0, stderr)
                self.assertNotIn("Traceback", stderr)
                self.assertIn(marker_path, stderr)
                with open(marker_path) as f:
                    self.assertEqual(json.load(f)["status"], "complete")  # the case ran again
        # The report, over a malformed marker and a series whose time is not a number.
        write(marker_path, b"[1, 2]")
        write(os.path.join(out, "first", "heart.pvd"),
              '<VTKFile type="Collection"><Collection><DataSet timestep="abc" file="h_0000.vtu"/></Collection>'
              '</VTKFile>')
        env = dict(os.environ)
        env.pop("DISPLAY", None)
        p = subprocess.run(CLI + ["report", os.path.join(out, "first")], capture_output=True, text=True,
                           timeout=300, env=env)
        self.assertNotIn("Traceback", p.stderr)
        self.assertIn(marker_path, p.stderr)
        page = os.path.join(out, "first", "report.html")
        self.assertIn("timestep 'abc' is not a number", p.stderr + (open(page).read() if os.path.exists(page) else ""))

    # -- readers -----------------------------------------------------------------------------------------
    def test_readers_refuse_what_would_block_them(self):
        fifo = os.path.join(ROOT, "fifo.nii")
        if not os.path.exists(fifo):
            os.mkfifo(fifo)
        loop = os.path.join(ROOT, "loop1")
        if not os.path.lexists(loop):
            os.symlink(os.path.join(ROOT, "loop2"), loop)
            os.symlink(loop, os.path.join(ROOT, "loop2"))
        for name, path, words in (("fifo", fifo, "a FIFO (named pipe), not a regular file"),
                                  ("loop", loop, "a symbolic link loop")):
            for kind in ("ImageReader", "MeditReader", "OpenCARPReader"):
                with self.subTest(name, kind=kind):
                    self.refused("%s_%s" % (name, kind), reading(path, kind), path, words)
        with self.subTest("fifo_in_a_dicom_folder"):
            folder = os.path.join(ROOT, "dicom_with_fifo")
            os.makedirs(folder, exist_ok=True)
            if not os.path.exists(os.path.join(folder, "slice.dcm")):
                os.mkfifo(os.path.join(folder, "slice.dcm"))
            self.refused("fifo_dicom", reading(folder), "slice.dcm", "a FIFO (named pipe), not a regular file")
        with self.subTest("fifo_as_an_analyze_data_file"):
            header = os.path.join(ROOT, "pair.hdr")
            hdr = bytearray(348)
            hdr[0:4] = (348).to_bytes(4, "little")
            for k, v in enumerate((3, 4, 4, 4, 1, 1, 1, 1)):  # dim
                hdr[40 + 2 * k:42 + 2 * k] = v.to_bytes(2, "little")
            hdr[70:72] = (2).to_bytes(2, "little")  # uint8
            hdr[72:74] = (8).to_bytes(2, "little")
            import struct
            for k in range(8):
                hdr[76 + 4 * k:80 + 4 * k] = struct.pack("<f", 1.0)
            hdr[344:348] = b"ni1\0"
            write(header, bytes(hdr))
            if not os.path.exists(os.path.join(ROOT, "pair.img")):
                os.mkfifo(os.path.join(ROOT, "pair.img"))
            self.refused("fifo_img", reading(header), "pair.img", "not a regular file")
        # The readers refuse them too, for Python and ParaView users (no pipeline check before them).
        script = textwrap.dedent("""
            import sys, anatomesh
            from vtkmodules.vtkCommonCore import vtkObject
            vtkObject.GlobalWarningDisplayOff()
            for cls in (anatomesh.amImageReader, anatomesh.amMeditReader, anatomesh.amOpenCARPReader):
                r = cls()
                r.SetFileName(sys.argv[1])
                r.Update()
            print("returned")
            """)
        p = subprocess.run([sys.executable, "-c", script, fifo], capture_output=True, text=True, timeout=60)
        self.assertIn("returned", p.stdout, p.stderr)

    def test_readers_refuse_what_they_would_read_wrong(self):
        degenerate = write(os.path.join(ROOT, "degenerate.mesh"),
                           "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                           "Tetrahedra\n1\n1 1 1 1 1\nEnd\n")
        write(os.path.join(ROOT, "degenerate_carp.pts"), "4\n0 0 0\n1000 0 0\n0 1000 0\n0 0 1000\n")
        write(os.path.join(ROOT, "degenerate_carp.elem"), "1\nTt 0 1 1 3 1\n")
        garbage = write(os.path.join(ROOT, "garbage.mesh"), bytes(random.Random(1).randrange(128, 256)
                                                                  for _ in range(3000)))
        self.refused("degenerate_medit", reading(degenerate, "MeditReader"), "uses vertex 1 twice")
        self.refused("degenerate_carp", reading(os.path.join(ROOT, "degenerate_carp.pts"), "OpenCARPReader"),
                     "appears twice")
        stderr = self.refused("garbage_medit", reading(garbage, "MeditReader"), "unknown or unsupported section",
                              "\\x")
        self.assertNotIn("failed: error", stderr)
        # A MetaImage header cut short: said so, not "No such file or directory" for a file that exists.
        header = write(os.path.join(ROOT, "cut.mha"), "ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\n")
        stderr = self.refused("cut_mha", reading(header), "ends without ElementDataFile")
        self.assertNotIn("No such file", stderr)

    def test_scan_where_a_label_map_belongs_is_refused_naming_the_file(self):
        out = os.path.join(ROOT, "scan")
        code, _, stderr = run("run", self.pipeline("scan.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              <Filter name="w" type="ImageWriter"><Input from="p" port="CT"/>
                <Property name="FileName" value="${output}/ct.nii.gz"/></Filter>
            </AnatomeshPipeline>"""), "--quiet", "--output", out)
        self.assertEqual(code, 0, stderr)
        scan = os.path.join(out, "ct.nii.gz")
        for kind in ("LabelSurface", "LabelMapTetrahedralize"):
            with self.subTest(kind):
                self.refused("scan_" + kind, """
                    <AnatomeshPipeline version="1">
                      <Filter name="r" type="ImageReader"><Property name="FileName" value="%s"/></Filter>
                      <Filter name="s" type="%s"><Input from="r"/></Filter>
                      <Output from="s" file="${output}/x.%s"/>
                    </AnatomeshPipeline>""" % (scan, kind, "vtp" if kind == "LabelSurface" else "vtu"),
                             "distinct values", "is this the scan", scan)

    def test_dicom_messages_whole_and_slices_named(self):
        abdomen = os.path.join(SHARED, "totalseg_abdomen_ct_labels", "example_ct_dicom")
        head = os.path.join(SHARED, "dcm_qa_ct_ge_head_tilt")
        if not (os.path.isdir(abdomen) and os.path.isdir(head)):
            self.skipTest("the shared DICOM series are absent")
        two = os.path.join(ROOT, "two_series")
        shutil.rmtree(two, ignore_errors=True)
        os.makedirs(two)
        n = 0
        for folder in (abdomen, head):
            for name in sorted(os.listdir(folder)):
                if name.endswith(".md"):
                    continue
                shutil.copyfile(os.path.join(folder, name), os.path.join(two, "%03d.dcm" % n))
                n += 1
        # The message lists both series and says what to set: its lines all reach the user.
        self.refused("two_series", reading(two), "holds 2 series", "set SeriesUID", ": 20 files, e.g.",
                     ": 28 files, e.g.")
        # A JPEG 2000 slice whose codestream header is damaged: refused, the slice named.
        broken = os.path.join(ROOT, "broken_j2k")
        shutil.rmtree(broken, ignore_errors=True)
        shutil.copytree(abdomen, broken)
        names = sorted(f for f in os.listdir(broken) if not f.endswith(".md"))
        victim = os.path.join(broken, names[10])
        os.chmod(victim, 0o644)
        data = bytearray(read(victim))
        start = data.find(b"\xff\x4f\xff\x51")  # the codestream's SOC and SIZ markers
        self.assertGreater(start, 0)
        data[start + 4:start + 68] = bytes((37 * i + 11) & 255 for i in range(64))
        write(victim, bytes(data))
        self.refused("broken_j2k", reading(broken), "cannot be decoded", victim)

    # -- properties and the same-file guard ------------------------------------------------------------------
    def test_integers_out_of_range_and_detached_data_files(self):
        self.refused("huge_seed", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Seed" value="99999999999999999999"/>
              </Filter>
              <Output from="p" port="CT" file="${output}/x.vti"/>
            </AnatomeshPipeline>""", "out of an integer's range", "Seed")
        # An input header whose data file is the output's: the output would overwrite the input's voxels.
        folder = os.path.join(ROOT, "detached")
        code, _, stderr = run("run", self.pipeline("detached_make.xml", """
            <AnatomeshPipeline version="1">
              <Filter name="p" type="ThoraxPhantomSource"><Property name="Spacing" value="8 8 8"/></Filter>
              <Filter name="w" type="ImageWriter"><Input from="p" port="CT"/>
                <Property name="FileName" value="${output}/in.mhd"/><Property name="UseCompression" value="0"/>
              </Filter>
            </AnatomeshPipeline>"""), "--quiet", "--output", folder)
        self.assertEqual(code, 0, stderr)
        header = os.path.join(folder, "in.mhd")
        write(header, read(header).replace(b"ElementDataFile = in.raw", b"ElementDataFile = out.raw"))
        os.rename(os.path.join(folder, "in.raw"), os.path.join(folder, "out.raw"))
        before = read(os.path.join(folder, "out.raw"))
        self.refused("detached", """
            <AnatomeshPipeline version="1">
              <Filter name="r" type="ImageReader"><Property name="FileName" value="%s"/></Filter>
              <Filter name="w" type="ImageWriter"><Input from="r"/>
                <Property name="FileName" value="%s/out.mhd"/><Property name="UseCompression" value="0"/></Filter>
            </AnatomeshPipeline>""" % (header, folder), "would overwrite the input", "out.raw")
        self.assertEqual(read(os.path.join(folder, "out.raw")), before)
        # A series whose frames would replace a file the pipeline reads.
        frame = os.path.join(folder, "heart_0001.vtu")
        write(frame, "<VTKFile/>")
        self.refused("frames", """
            <AnatomeshPipeline version="1">
              <Filter name="r" type="OpenCARPReader"><Property name="FileName" value="%s"/></Filter>
              <Output from="r" file="%s/heart.pvd"/>
            </AnatomeshPipeline>""" % (frame, folder), "would overwrite the input")


if __name__ == "__main__":
    unittest.main()
