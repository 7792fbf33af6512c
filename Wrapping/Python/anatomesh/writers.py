"""The run's output files: tables as CSV, data sets and time series as VTK XML, each written whole or not
at all (anatomesh.atomic), VTK XML files on the concurrent writer's threads."""
import os
import re

from . import atomic
from .errors import PipelineError
from .watch import WRITING, StageClock


def column_header(array):
    """A column's name, with its unit when the array records one (vtkDataArray::UNITS_LABEL):
    "Volume_mm3", "Time_ms", "I_mV"."""
    from vtkmodules.vtkCommonCore import vtkDataArray
    name = array.GetName() or ""
    info = array.GetInformation()
    key = vtkDataArray.UNITS_LABEL()
    unit = info.Get(key) if info is not None and info.Has(key) else ""
    return name + "_" + unit if unit and not name.endswith("_" + unit) else name


def write_csv(table, path):
    """A vtkTable as comma-separated values with a header row (units in the names), written atomically."""
    if table is None or not table.IsA("vtkTable"):
        raise PipelineError("%s: .csv takes a table, got %s" % (path, table.GetClassName() if table else "nothing"))
    columns = [table.GetColumn(c) for c in range(table.GetNumberOfColumns())]
    with atomic.replacing(path) as tmp:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(",".join(column_header(c) for c in columns) + "\n")
            for r in range(table.GetNumberOfRows()):
                f.write(",".join("%.10g" % c.GetTuple1(r) if c.IsNumeric() else str(c.GetValue(r))
                                 for c in columns) + "\n")


def _finish(files):
    """Wait for the files queued; a failure (a full disk, say) is an error naming the file."""
    if not files.Finish():
        raise PipelineError(files.GetErrorMessage())


class _Series:
    """A time series' frames, written into a staging folder beside the .pvd (.STEM.tmpPID.frames) and
    moved into place with the .pvd written last by commit(): a failed run leaves the old series (frames and
    .pvd) as it was. discard() removes the staging folder of a series not committed."""

    def __init__(self, folder, stem, path):
        atomic.remove_stale(folder, re.compile(r"^\.%s\.tmp(\d+)\.frames$" % re.escape(stem)))
        self.folder, self.path, self.names, self.text = folder, path, [], None
        self.staging = os.path.join(folder, ".%s.tmp%d.frames" % (stem, os.getpid()))
        self.discard()  # this process's own, from an earlier series of the same name
        try:
            os.mkdir(self.staging)
        except OSError as e:
            raise OSError(e.errno, e.strerror, path) from None

    def named(self, message):
        """A message about a staged frame, naming the series and the frame."""
        prefix = self.staging + os.sep
        if message.startswith(prefix):
            frame, _, why = message[len(prefix):].partition(": ")
            return "%s: frame %s: %s" % (self.path, frame, why)
        return message.replace(prefix, self.folder + os.sep)

    def commit(self):
        try:
            for name in self.names:
                os.replace(os.path.join(self.staging, name), os.path.join(self.folder, name))
        except OSError as e:
            raise OSError(e.errno, e.strerror, self.path) from None
        atomic.write_text(self.path, self.text)
        self.discard()

    def discard(self):
        import shutil
        shutil.rmtree(self.staging, ignore_errors=True)


def write_time_series(algorithm, port, path, error=lambda: None, clock=None, files=None, collections=None):
    """Write every time step an algorithm's output port advertises as NAME_NNNN.vtu (or .vtp/.vti)
    beside a ParaView collection NAME.pvd; without time steps, one file. The frames are staged and moved
    into place with the .pvd written last (see _Series), so a failed run never leaves a collection naming
    missing files, nor new frames under an old collection. Returns the paths written.
    With 'files' (an amConcurrentXMLWriter) the frames are queued there, and the series (a _Series) is
    appended to 'collections', to commit once the queue is finished (or discard after a failure)."""
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
    algorithm.UpdateInformation()
    info = algorithm.GetOutputInformation(port)
    times = list(info.Get(sddp.TIME_STEPS())) if info.Has(sddp.TIME_STEPS()) else [None]
    folder = os.path.dirname(os.path.abspath(path))
    stem = os.path.splitext(os.path.basename(path))[0]
    exts = {"vtkUnstructuredGrid": ".vtu", "vtkPolyData": ".vtp", "vtkImageData": ".vti"}
    entries, written = [], []
    series = _Series(folder, stem, path)
    if collections is not None:
        collections.append(series)
    try:
        for k, t in enumerate(times):
            if t is None:
                algorithm.Update(port)
            else:
                algorithm.UpdateTimeStep(t)
            data = algorithm.GetOutputDataObject(port)
            message = error()
            if message or data is None:
                raise PipelineError("%s: time step %s failed: %s" % (path, t, message or "no output"))
            ext = exts.get(data.GetClassName())
            if ext is None:
                raise PipelineError("%s: cannot write a %s as a time series" % (path, data.GetClassName()))
            name = "%s_%04d%s" % (stem, k, ext)
            with (clock or StageClock()).running(WRITING):
                try:
                    write_vtk_xml(data, os.path.join(series.staging, name), files)
                except PipelineError as e:
                    raise PipelineError(series.named(str(e))) from None
            series.names.append(name)
            written.append(os.path.join(folder, name))
            entries.append('    <DataSet timestep="%r" part="0" file="%s"/>' % (0.0 if t is None else t, name))
        series.text = ('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n'
                       + "\n".join(entries) + "\n  </Collection>\n</VTKFile>\n")
        written.append(path)
        if files is None:
            series.commit()
    finally:
        if files is None:
            series.discard()
    return written


def _plain_field_data(data):
    """A shallow copy whose field data other readers take too (meshio reads no String arrays and no empty
    ones): text arrays become UTF-8 bytes (UInt8, one line per value; bytes(array).decode() gives the text),
    empty arrays are left out."""
    from vtkmodules.vtkCommonCore import vtkStringArray, vtkUnsignedCharArray
    fields = data.GetFieldData()
    if fields is None:
        return data
    if all(fields.GetAbstractArray(i).GetNumberOfTuples() > 0 and not fields.GetAbstractArray(i).IsA("vtkStringArray")
           for i in range(fields.GetNumberOfArrays())):
        return data
    copy = data.NewInstance()
    copy.ShallowCopy(data)
    plain = copy.GetFieldData().NewInstance()
    for i in range(fields.GetNumberOfArrays()):
        array = fields.GetAbstractArray(i)
        if array.GetNumberOfTuples() == 0:
            continue
        if isinstance(array, vtkStringArray):
            text = "\n".join(array.GetValue(k) for k in range(array.GetNumberOfValues())).encode("utf-8")
            import numpy as np
            from vtkmodules.util.numpy_support import numpy_to_vtk
            encoded = numpy_to_vtk(np.frombuffer(text, dtype=np.uint8), deep=1,
                                   array_type=vtkUnsignedCharArray().GetDataType())
            encoded.SetName(array.GetName())
            plain.AddArray(encoded)
        else:
            plain.AddArray(array)
    copy.SetFieldData(plain)
    return copy


def write_vtk_xml(data, path, files=None):
    """Write a data object to a VTK XML file (.vti, .vtp, .vtu, .vtm), or a table to .csv, atomically.
    A .vti, .vtp or .vtu goes through amConcurrentXMLWriter (its format settings are the project's
    one copy): queued on 'files' when given (written on a worker thread, done when files.Finish()
    returns), else written before this returns."""
    holds = {".vti": "vtkImageData", ".vtp": "vtkPolyData", ".vtu": "vtkUnstructuredGrid",
             ".vtm": "vtkMultiBlockDataSet"}
    ext = os.path.splitext(path)[1].lower()
    if ext == ".csv":
        write_csv(data, path)
        return
    if ext not in holds:
        raise PipelineError("%s: unknown output extension %r (use %s)" % (path, ext, ", ".join(sorted(holds))))
    if not data.IsA(holds[ext]):
        fits = [e for e, kind in sorted(holds.items()) if data.IsA(kind)]
        raise PipelineError("%s: a %s file holds a %s, but this output is a %s%s" % (
            path, ext, holds[ext], data.GetClassName(), " (use %s)" % fits[0] if fits else ""))
    if ext != ".vtm":
        from anatomesh import amConcurrentXMLWriter
        queue = files if files is not None else amConcurrentXMLWriter()
        if not queue.Write(_plain_field_data(data), path):
            raise PipelineError(queue.GetErrorMessage())
        if files is None:
            _finish(queue)
        return
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter
    writer = vtkXMLMultiBlockDataWriter()
    # As amConcurrentXMLWriter writes: inline base64 (Debian 12's expat breaks VTK 9.2's reading of
    # appended data), zlib's fastest level.
    writer.SetDataModeToBinary()
    writer.SetCompressorTypeToZLib()
    writer.SetCompressionLevel(1)
    writer.SetInputData(data)
    _write_multiblock(writer, path)


def _write_multiblock(writer, path):
    """VTK writes a .vtm's blocks into a folder named after it, which the .vtm names: both are written in a
    temporary folder beside the target, then the blocks' folder and the .vtm are moved into place."""
    import shutil
    import tempfile
    folder, base = os.path.split(os.path.abspath(path))
    stem = os.path.splitext(base)[0]
    try:
        work = tempfile.mkdtemp(prefix=".%s.tmp%d_" % (stem, os.getpid()), dir=folder)
    except OSError as e:
        raise OSError(e.errno, e.strerror, path) from None
    try:
        writer.SetFileName(os.path.join(work, base))
        if not writer.Write() or writer.GetErrorCode() or not os.path.exists(os.path.join(work, base)):
            raise PipelineError("%s: the VTK XML writer failed (a full disk, or no %s data)" % (
                path, writer.GetInput().GetClassName()))
        blocks, target = os.path.join(work, stem), os.path.join(folder, stem)
        if os.path.isdir(blocks):
            if os.path.isdir(target):
                os.rename(target, os.path.join(work, "old"))
            os.rename(blocks, target)
        with atomic.replacing(path) as tmp:
            os.rename(os.path.join(work, base), tmp)
    except OSError as e:
        raise OSError(e.errno, e.strerror, path) from None
    finally:
        shutil.rmtree(work, ignore_errors=True)
