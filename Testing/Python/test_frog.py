"""The frog tissue label map of ../shared/data (15 organs) meshed end to end by
Examples/Pipelines/frog.xml (skipped when the data is absent): every organ is present in the
tetrahedral mesh, no tetrahedron is inverted, each organ's volume within 2 % of its voxel volume
(every organ is at least 1 cm3), and the Medit file carries the organs' interface triangles.
"""
import os
import subprocess
import sys
import unittest

SOURCE = os.environ.get("ANATOMESH_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
SHARED = os.environ.get("ANATOMESH_SHARED_DATA", os.path.join(SOURCE, "..", "shared", "data"))
TMP = os.environ.get("ANATOMESH_TEST_TMP", "/tmp")
FROG = os.path.join(SHARED, "vtk_frog_tissue_labels", "frogtissue.mhd")


@unittest.skipUnless(os.path.exists(FROG), "shared frog label map absent: " + FROG)
class FrogEndToEnd(unittest.TestCase):
    def test_every_organ_meshed(self):
        import numpy as np
        import anatomesh
        from vtkmodules.util.numpy_support import vtk_to_numpy
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
        out = os.path.join(TMP, "frog")
        cli = [sys.executable, os.path.join(SOURCE, "Wrapping", "anatomesh"), "run",
               os.path.join(SOURCE, "Examples", "Pipelines", "frog.xml"),
               "--set", "input=" + FROG, "--output", out, "--quiet"]
        p = subprocess.run(cli, capture_output=True, text=True, timeout=900)
        self.assertEqual(p.returncode, 0, p.stderr)

        labels = anatomesh.amImageReader()
        labels.SetFileName(os.path.join(out, "frog_labels.nii.gz"))
        labels.Update()
        image = labels.GetOutput()
        voxel = np.prod(image.GetSpacing())
        values, counts = np.unique(vtk_to_numpy(image.GetPointData().GetScalars()), return_counts=True)
        voxel_volume = {int(v): c * voxel for v, c in zip(values, counts) if v != 0}
        self.assertEqual(sorted(voxel_volume), list(range(1, 16)))  # stray labels 16-29 cleaned away

        r = vtkXMLUnstructuredGridReader()
        r.SetFileName(os.path.join(out, "frog_tets.vtu"))
        r.Update()
        mesh = r.GetOutput()
        region = vtk_to_numpy(mesh.GetCellData().GetArray("Region"))
        volume = vtk_to_numpy(mesh.GetCellData().GetArray("Volume"))
        self.assertTrue(np.all(volume > 0))
        print("organ  voxel cm3  mesh cm3")
        for label in range(1, 16):
            v = volume[region == label].sum()
            print("%5d %10.2f %9.2f" % (label, voxel_volume[label] / 1e3, v / 1e3))
            self.assertGreater(v, 0, "organ %d missing" % label)
            # LabelMapTetrahedralize's PreserveVolumes gives the thin organs (nerve, retina) back
            # what CGAL's chords take (up to 19 % without it).
            self.assertGreaterEqual(voxel_volume[label], 1000.0)
            self.assertLess(abs(v - voxel_volume[label]), 0.02 * voxel_volume[label], "organ %d" % label)

        medit = anatomesh.amMeditReader()
        medit.SetFileName(os.path.join(out, "frog_tets.mesh"))
        medit.Update()
        back = medit.GetOutput()
        refs = vtk_to_numpy(back.GetCellData().GetArray("Region"))
        types = np.array([back.GetCellType(c) for c in range(back.GetNumberOfCells())])
        triangle_refs = set(refs[types == 5].tolist())
        self.assertTrue({1000 * label for label in range(1, 16)} & triangle_refs)  # outer surfaces
        self.assertEqual(int(np.sum(types == 10)), mesh.GetNumberOfCells())


if __name__ == "__main__":
    unittest.main()
