"""The report's tables as HTML: the paper's Table 1 beside ours, region volumes, interface
distances, Dice, the run's variables."""
import html

from .. import adult_volumes
from .collect import base

# The CEMRACS 2004 paper's whole-mesh row (Table 1): vertices, tetrahedra, mean and worst quality.
PAPER = {"np": "261 000", "ne": "1 530 000", "MeanQuality": "1.56", "MaximumQuality": "47.9"}


def _table(head, rows, caption=None):
    out = ["<table>"]
    if caption:
        out.append("<caption>%s</caption>" % html.escape(caption))
    out.append("<tr>%s</tr>" % "".join("<th>%s</th>" % html.escape(str(h)) for h in head))
    for row in rows:
        out.append("<tr>%s</tr>" % "".join("<td>%s</td>" % html.escape(str(c)) for c in row))
    out.append("</table>")
    return "\n".join(out)


def _num(text, digits=3):
    try:
        v = float(text)
    except ValueError:
        return text
    return "%d" % v if v == int(v) and abs(v) >= 1 else "%.*g" % (digits + 1, v)


def _name(names, label):
    return names[label] if names and 0 <= label < len(names) else ""


def quality(head, rows, names=None):
    """Table 1: per region and whole mesh (region -1), then the paper's whole-mesh row."""
    cols = ["Region", "np", "nt", "ne", "MeanQuality", "MaximumQuality", "MinimumDihedralAngle", "Volume"]
    plain = [base(h) for h in head]  # without the units ("Volume_mm3")
    index = [plain.index(c) for c in cols if c in plain]
    shown = [c for c in cols if c in plain]
    body = []
    for r in rows:
        cells = [r[i] for i in index]
        label = int(float(cells[0])) if shown[0] == "Region" else 0
        cells[0] = "whole mesh" if label == -1 else ("%d %s" % (label, _name(names, label))).strip()
        body.append([cells[0]] + [_num(c) for c in cells[1:]])
    body.append(["paper (whole mesh)"] + [PAPER.get(c, "") for c in shown[1:]])
    return _table(["region", "vertices", "surface triangles", "tetrahedra", "mean Q", "worst Q", "smallest dihedral (deg)",
                   "volume (mm3)"][:len(shown)], body, "Quality per region (the paper's Table 1)")


def region_volumes(array, names=None):
    """RegionVolumes field data: label, voxel mm3, mesh mm3, relative difference; each organ beside its
    adult range."""
    rows = []
    for i in range(array.GetNumberOfTuples()):
        label, voxels, mesh, diff = array.GetTuple4(i)
        name = _name(names, int(label))
        adult = adult_volumes.RANGES.get(name)
        where = adult_volumes.verdict(name, mesh / 1000.0)
        rows.append([("%d %s" % (label, name)).strip(), "%.4g" % (voxels / 1000.0), "%.4g" % (mesh / 1000.0),
                     "%+.2f %%" % (100.0 * diff),
                     "%d-%d%s" % (adult[0], adult[1], " (%s)" % where if where else "") if adult else ""])
    return _table(["region", "voxels (cm3)", "mesh (cm3)", "difference", "adult range (cm3)"], rows,
                  "Region volumes: the mesh against its label map, each organ beside an adult's")


def interfaces(array, tolerance=None, names=None, limit=15):
    """InterfaceHausdorff field data (lower, higher, distance): the largest first."""
    rows = sorted((array.GetTuple3(i) for i in range(array.GetNumberOfTuples())), key=lambda r: -r[2])
    def side(label):
        return "outside" if label == 0 else ("%d %s" % (label, _name(names, int(label)))).strip()
    body = [[side(int(hi)), side(int(lo)), "%.3f" % d, "" if tolerance is None else ("above" if d > tolerance else "")]
            for lo, hi, d in rows[:limit]]
    caption = "Largest distance to the input per interface (%d interfaces%s)" % (
        len(rows), ", the %d largest shown" % limit if len(rows) > limit else "")
    return _table(["region", "meets", "distance (mm)", "tolerance"], body, caption)


def dice(head, rows, names=None):
    li, di = head.index("Label"), head.index("Dice")
    body = [[("%d %s" % (int(float(r[li])), _name(names, int(float(r[li]))))).strip(), "%.4f" % float(r[di])]
            for r in rows if int(float(r[li])) > 0]
    return _table(["label", "Dice"], body, "Segmentation against the reference")


def ecg_features(head, rows, names=None):
    """The ECG's reading per lead (LeadFieldECG's Features table)."""
    columns = [head.index(c) for c in ("Lead", "R_mV", "S_mV", "T_mV", "TPolarity")]
    body = [[r[columns[0]], _num(r[columns[1]]), _num(r[columns[2]]), _num(r[columns[3]]), r[columns[4]]]
            for r in rows]
    return _table(["lead", "R (mV)", "S (mV)", "T (mV)", "T wave"], body, "The ECG read per lead")


def variables(record):
    rows = [[k, v] for k, v in sorted((record or {}).get("variables", {}).items())]
    return _table(["variable", "value"], rows, "Pipeline variables")
