"""Adult reference volumes (cm3) of the organs of the thorax label scheme, for the run's summary and
the report: lungs at inspiration (each 1-4 L), the ventricles' wall (LV and RV together, 100-350 g
at 1.05 g/cm3), end-diastolic blood pools (LV 65-240 mL, RV 60-260 mL), the atria (a left atrium of
20-100 mL, and the right one's where clicked), the thoracic aorta."""

RANGES = {"RightLung": (1000, 4000), "LeftLung": (900, 3600), "Myocardium": (100, 350),
          "LeftVentricleBlood": (65, 240), "RightVentricleBlood": (60, 260), "Aorta": (20, 200),
          "Atria": (20, 200)}


def verdict(name, cm3):
    """'' inside the organ's adult range (or for an organ without one), else 'below' or 'above'."""
    if name not in RANGES:
        return ""
    low, high = RANGES[name]
    return "below" if cm3 < low else "above" if cm3 > high else ""


def remark(name, cm3):
    """The organ's adult range, and whether the volume lies outside it."""
    if name not in RANGES:
        return ""
    low, high = RANGES[name]
    where = verdict(name, cm3)
    return "   adult %d-%d cm3%s" % (low, high, " (%s)" % where if where else "")
