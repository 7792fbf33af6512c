"""The mesh files as the solvers' own readers take them: meshio reads the XDMF mesh and facets (cell and
facet tags, names), the Gmsh and openCARP files; every file holds only points that elements use; FEniCSx
(python3-dolfinx) loads the Gmsh file and the XDMF files (HDF5) with their cell and facet tags and solves a
Poisson problem with a conductivity per region on each."""
import json
import os
import subprocess
import sys
import tempfile
import textwrap
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

    def test_fenicsx_loads_the_gmsh_and_xdmf_files_and_solves_on_them(self):
        # In its own process: dolfinx's MPI build of HDF5 and ParaView's do not share a process.
        probe = subprocess.run([sys.executable, "-c", "import dolfinx"], capture_output=True, text=True)
        if probe.returncode != 0:
            self.skipTest("python3-dolfinx is not installed")
        for name, writer in (("phantom_fenicsx.msh", anatomesh.amGmshWriter()),
                             ("phantom_fenicsx.xdmf", anatomesh.amXdmfWriter())):
            with self.subTest(name):
                self.fenicsx_solves_on(os.path.join(self.folder, name), writer)

    def fenicsx_solves_on(self, path, writer):
        writer.SetInputData(self.mesh)
        writer.SetFileName(path)
        self.assertEqual(writer.Write(), 1)
        p = subprocess.run([sys.executable, "-c", FENICSX, path], capture_output=True, text=True, timeout=600)
        self.assertEqual(p.returncode, 0, p.stderr[-3000:])
        got = json.loads(p.stdout.strip().splitlines()[-1])
        regions = vtk_to_numpy(self.mesh.GetCellData().GetArray("Region"))
        self.assertEqual(got["cells"], self.mesh.GetNumberOfCells())
        self.assertEqual(got["points"], self.mesh.GetNumberOfPoints())
        # Every region's volume as FEniCSx integrates it over its cell tag: the mesh's own.
        from vtkmodules.vtkFiltersVerdict import vtkMeshQuality
        volume = vtkMeshQuality()
        volume.SetInputData(self.mesh)
        volume.SetTetQualityMeasureToVolume()
        volume.Update()
        v = vtk_to_numpy(volume.GetOutput().GetCellData().GetArray("Quality"))
        for tag in sorted(set(regions.tolist())):
            self.assertAlmostEqual(got["volumes"][str(tag)] / v[regions == tag].sum(), 1.0, places=9)
        # The facet tags: the outer surface (region | 0) and the LV endocardium (6 | 5) among them.
        self.assertIn(6005, got["facet_tags"])
        self.assertTrue(any(t % 1000 == 0 for t in got["facet_tags"]))
        # The Poisson problem: Galerkin's energy identity holds to the solver's tolerance, and the solution
        # is positive inside, zero on the outer surface.
        self.assertLess(abs(got["energy"] - got["work"]) / got["work"], 1e-6)
        self.assertGreater(got["max_u"], 0)
        self.assertLess(got["boundary_u"], 1e-6 * got["max_u"])


# Loads a .msh through Gmsh's API and dolfinx.io.gmshio.model_to_mesh (Debian's dolfinx 0.5.2
# read_from_msh returns an undefined name), or an .xdmf and its facets through XDMFFile, then solves -div(sigma grad u) = 1 in the myocardium, u = 0 on
# the outer surface, sigma per region (S/m: lungs 0.04, fat 0.04, blood 0.7, bone 0.02, the rest 0.2).
FENICSX = textwrap.dedent("""
    import json, sys
    import numpy as np
    import gmsh
    from mpi4py import MPI
    import ufl
    from dolfinx import fem, io
    from dolfinx.io import gmshio
    from dolfinx.fem.petsc import LinearProblem
    if sys.argv[1].endswith(".msh"):
        gmsh.initialize()
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.merge(sys.argv[1])
        domain, cells, facets = gmshio.model_to_mesh(gmsh.model, MPI.COMM_WORLD, 0, gdim=3)
        gmsh.finalize()
    else:
        with io.XDMFFile(MPI.COMM_WORLD, sys.argv[1], "r") as f:
            domain = f.read_mesh(name="mesh")
            domain.topology.create_connectivity(3, 0)
            cells = f.read_meshtags(domain, name="mesh")
        domain.topology.create_connectivity(2, 3)
        with io.XDMFFile(MPI.COMM_WORLD, sys.argv[1][:-5] + "_facets.xdmf", "r") as f:
            facets = f.read_meshtags(domain, name="facet_tags")
    dx = ufl.Measure("dx", domain=domain, subdomain_data=cells)
    tags = sorted(set(cells.values.tolist()))
    volumes = {str(t): fem.assemble_scalar(fem.form(1.0 * dx(t))) for t in tags}
    conductivity = {2: 0.04, 3: 0.04, 4: 0.04, 6: 0.7, 7: 0.7, 8: 0.7, 9: 0.02, 10: 0.02}
    Q = fem.FunctionSpace(domain, ("DG", 0))
    sigma = fem.Function(Q)
    sigma.x.array[cells.indices] = [conductivity.get(int(t), 0.2) for t in cells.values]
    V = fem.FunctionSpace(domain, ("CG", 1))
    outer = facets.indices[facets.values % 1000 == 0]
    dofs = fem.locate_dofs_topological(V, 2, outer)
    zero = fem.dirichletbc(np.float64(0), dofs, V)
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    a = ufl.inner(sigma * ufl.grad(u), ufl.grad(v)) * dx
    L = 1.0 * v * dx(5)
    uh = LinearProblem(a, L, bcs=[zero], petsc_options={"ksp_type": "cg", "pc_type": "gamg", "ksp_rtol": 1e-12,
                                                        "ksp_max_it": 2000}).solve()
    energy = fem.assemble_scalar(fem.form(ufl.inner(sigma * ufl.grad(uh), ufl.grad(uh)) * dx))
    work = fem.assemble_scalar(fem.form(uh * dx(5)))
    print(json.dumps({"cells": domain.topology.index_map(3).size_local,
                      "points": domain.geometry.x.shape[0], "volumes": volumes,
                      "facet_tags": sorted(set(facets.values.tolist())), "energy": energy, "work": work,
                      "max_u": float(uh.x.array.max()), "boundary_u": float(abs(uh.x.array[dofs]).max())}))
    """)


if __name__ == "__main__":
    unittest.main()
