"""The mesh files as the solvers' own readers take them: meshio reads the XDMF mesh and facets (cell and
facet tags, names), the Gmsh and openCARP files; every file holds only points that elements use.
FEniCSx itself (python3-dolfinx) is not yet among the clients tested here."""
import os
import tempfile
import unittest

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import anatomesh

TMP = os.environ.get("ANATOMESH_TEST_TMP", tempfile.gettempdir())


def phantom_mesh():
    phantom = anatomesh.amThoraxPhantomSource()
    phantom.SetSpacing(4, 4, 4)
    mesher = anatomesh.amLabelMapTetrahedralize()
    mesher.SetInputConnection(phantom.GetOutputPort(1))
    mesher.SetFacetSize(8)
    mesher.SetCellSize(12)
    mesher.SetFacetDistance(1.5)
    mesher.Update()
    return mesher.GetOutputDataObject(0)


class SolverClients(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.mesh = phantom_mesh()
        cls.folder = os.path.join(TMP, "solver_clients")
        os.makedirs(cls.folder, exist_ok=True)

    def test_xdmf_mesh_and_facets_through_meshio(self):
        import meshio
        path = os.path.join(self.folder, "phantom.xdmf")
        writer = anatomesh.amXdmfWriter()
        writer.SetInputData(self.mesh)
        writer.SetFileName(path)
        self.assertEqual(writer.Write(), 1)
        mesh = meshio.read(path)
        regions = vtk_to_numpy(self.mesh.GetCellData().GetArray("Region"))
        self.assertEqual(len(mesh.cells), 1)
        self.assertEqual(mesh.cells[0].type, "tetra")
        self.assertEqual(len(mesh.cells[0].data), self.mesh.GetNumberOfCells())
        np.testing.assert_array_equal(mesh.cell_data["cell_tags"][0], regions)
        # Every point in a tetrahedron.
        self.assertEqual(len(np.unique(mesh.cells[0].data)), len(mesh.points))
        self.assertEqual(mesh.field_data["Myocardium"][0], 5)
        facets = meshio.read(os.path.join(self.folder, "phantom_facets.xdmf"))
        self.assertEqual(facets.cells[0].type, "triangle")
        tags = set(facets.cell_data["facet_tags"][0].tolist())
        self.assertIn(6005, tags)  # LV blood | myocardium, the LV endocardium
        self.assertTrue(any(t % 1000 == 0 for t in tags), tags)  # the body surface: a region | outside
        np.testing.assert_array_equal(facets.points, mesh.points)

    def test_xdmf_carries_the_fibres(self):
        import meshio
        fibres = anatomesh.amVentricularFibres()
        fibres.SetInputData(self.mesh)
        fibres.Update()
        path = os.path.join(self.folder, "phantom_fibres.xdmf")
        writer = anatomesh.amXdmfWriter()
        writer.SetInputConnection(fibres.GetOutputPort(0))
        writer.SetFileName(path)
        self.assertEqual(writer.Write(), 1)
        mesh = meshio.read(path)
        expected = vtk_to_numpy(fibres.GetOutputDataObject(0).GetCellData().GetArray("Fibers"))
        np.testing.assert_allclose(mesh.cell_data["Fibers"][0], expected, rtol=0, atol=1e-6)
        self.assertEqual(mesh.cell_data["Sheets"][0].shape, (self.mesh.GetNumberOfCells(), 3))

    def test_gmsh_and_opencarp_files_hold_only_used_points(self):
        import meshio
        gmsh = os.path.join(self.folder, "phantom.msh")
        writer = anatomesh.amGmshWriter()
        writer.SetInputData(self.mesh)
        writer.SetFileName(gmsh)
        self.assertEqual(writer.Write(), 1)
        mesh = meshio.read(gmsh)
        used = np.unique(np.concatenate([block.data.ravel() for block in mesh.cells]))
        self.assertEqual(len(used), len(mesh.points))
        carp = anatomesh.amOpenCARPWriter()
        carp.SetInputData(self.mesh)
        carp.SetFileName(os.path.join(self.folder, "phantom"))
        self.assertEqual(carp.Write(), 1)
        reader = anatomesh.amOpenCARPReader()
        reader.SetFileName(os.path.join(self.folder, "phantom.pts"))
        reader.Update()
        back = reader.GetOutput()
        self.assertEqual(back.GetNumberOfCells(), self.mesh.GetNumberOfCells())
        self.assertEqual(back.GetNumberOfPoints(), self.mesh.GetNumberOfPoints())
        np.testing.assert_allclose(vtk_to_numpy(back.GetPoints().GetData()),
                                   vtk_to_numpy(self.mesh.GetPoints().GetData()), rtol=0, atol=1e-12)


if __name__ == "__main__":
    unittest.main()
