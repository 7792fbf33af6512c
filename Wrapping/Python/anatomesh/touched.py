"""The files a reader or a writer touches: its own file, and those beside it that its format implies (a
detached header's data file, the label tables written beside a label map, an openCARP mesh's parts, an XDMF
mesh's facets and HDF5 files, a time series' frames). The pipeline's same-file guard compares all of them."""
import errno
import os
import re
import stat

IMAGES = (".nii", ".nii.gz", ".nrrd", ".nhdr", ".mha", ".mhd")


def _stem(path, endings):
    lower = path.lower()
    for e in endings:
        if lower.endswith(e):
            return path[:-len(e)]
    return None


def _header_data_file(header, separator, keys):
    """The data file a detached header names (MetaImage's "ElementDataFile = x", NRRD's "data file: x"), or
    None (data in the header, a list, a pattern)."""
    try:
        with open(header, "rb") as f:
            text = f.read(1 << 16).decode("latin-1")
    except OSError:
        return None
    for line in text.splitlines():
        key, sep, value = line.partition(separator)
        if sep and key.strip().lower() in keys:
            name = value.strip()
            if not name or name.upper() in ("LOCAL", "LIST") or "%" in name or " " in name:
                return None
            return os.path.join(os.path.dirname(os.path.abspath(header)), name)
    return None


def sidecars(path):
    """The tables an image writer writes beside a label map (ITK-SNAP's, and ParaView's colours): the same
    for the map written in two formats (labels.nii and labels.nrrd), so two outputs may share them."""
    image = _stem(path, IMAGES)
    return [] if image is None else [image + ".ctbl", image + ".itksnap.txt"]


def paths(path, writing):
    """The files reading or writing 'path' touches besides the sidecars, 'path' first."""
    out = [path]
    image = _stem(path, IMAGES)
    if image is not None:
        if path.lower().endswith(".mhd"):
            data = _header_data_file(path, "=", ("elementdatafile",)) if not writing else None
            out += [data] if data else ([image + ".raw", image + ".zraw"] if writing else [])
        if path.lower().endswith(".nhdr") and not writing:
            data = _header_data_file(path, ":", ("data file", "datafile"))
            out += [data] if data else []
    base = _stem(path, (".pts", ".elem", ".lon"))
    if base is not None or (not writing and os.path.exists(path + ".pts")):
        base = path if base is None else base
        out += [base + e for e in (".pts", ".elem", ".lon") if base + e != path]
    xdmf = _stem(path, (".xdmf",))
    if xdmf is not None:  # the facets, and both files' HDF5 heavy data
        out += [xdmf + "_facets.xdmf", xdmf + ".h5", xdmf + "_facets.h5"]
    return out


def series_pattern(path):
    """For an output that writes files by a pattern (a .pvd's frames, openCARP's tagged surfaces), the
    regular expression their real paths match; else None."""
    real = os.path.realpath(path)
    stem = _stem(real, (".pvd",))
    if stem is not None:
        return re.compile(re.escape(stem) + r"_\d{4}\.vt[upi]$")
    base = _stem(real, (".pts", ".elem", ".lon"))
    if base is not None:
        return re.compile(re.escape(base) + r"\.[^/]+\.(surf|vtx)$")
    return None


def unreadable(path):
    """Why an input cannot be read as a file (or a DICOM folder), or None: missing, a symbolic link loop, a
    FIFO or a device (a reader would block on it or read garbage)."""
    for candidate in (path, path + ".pts"):  # .pts: openCARP's base name
        try:
            st = os.stat(candidate)
        except OSError as e:
            if e.errno == errno.ELOOP:
                return "is a symbolic link loop"
            if e.errno not in (errno.ENOENT, errno.ENOTDIR):
                return "cannot be read: %s" % e.strerror
            continue
        if stat.S_ISDIR(st.st_mode) or stat.S_ISREG(st.st_mode):
            return None
        kind = "a FIFO (named pipe)" if stat.S_ISFIFO(st.st_mode) else \
            "a socket" if stat.S_ISSOCK(st.st_mode) else "a device"
        return "is %s, not a regular file" % kind
    return "does not exist"
