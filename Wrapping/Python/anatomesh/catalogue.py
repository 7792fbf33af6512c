"""The filter catalogue: the ParaView plugin's server-manager XML, read as data.

One source of truth: the proxies, their VTK classes and their properties (name, Set-method,
type, number of values, defaults, domains) come from the same XML files the ParaView plugin
loads, shipped inside this package under ``servermanager/``.
"""
import glob
import os
import xml.etree.ElementTree as ET

PREFIX = "Anatomesh"

_TYPES = {
    "IntVectorProperty": "int",
    "DoubleVectorProperty": "double",
    "StringVectorProperty": "string",
    "IdTypeVectorProperty": "int",
    "InputProperty": "input",
}


class Property:
    """One server-manager property of a proxy."""

    def __init__(self, element):
        self.name = element.get("name")
        self.command = element.get("command")
        self.kind = _TYPES[element.tag]
        self.number_of_elements = int(element.get("number_of_elements", "1"))
        self.repeat_command = element.get("repeat_command") == "1"
        self.per_command = int(element.get("number_of_elements_per_command", "1"))
        self.clean_command = element.get("clean_command")
        # ParaView's indexed form: set_number_command(groups), then command(i, group...) per group.
        self.set_number_command = element.get("set_number_command")
        self.use_index = element.get("use_index") == "1"
        self.port_index = int(element.get("port_index", "0"))
        self.optional = element.find("Hints/Optional") is not None
        defaults = element.get("default_values")
        self.defaults = defaults.split() if defaults is not None else None
        self.boolean = element.find("BooleanDomain") is not None
        self.range = None
        self.enumeration = None
        rng = element.find("IntRangeDomain")
        if rng is None:
            rng = element.find("DoubleRangeDomain")
        if rng is not None:
            conv = int if self.kind == "int" else float
            lo, hi = rng.get("min"), rng.get("max")
            self.range = ([conv(v) for v in lo.split()] if lo else None,
                          [conv(v) for v in hi.split()] if hi else None)
        enum = element.find("EnumerationDomain")
        if enum is not None:
            self.enumeration = {e.get("text"): int(e.get("value")) for e in enum.findall("Entry")}
        doc = element.find("Documentation")
        self.documentation = " ".join(doc.text.split()) if doc is not None and doc.text else ""

    def __repr__(self):
        return "Property(%s, %s x%d)" % (self.name, self.kind, self.number_of_elements)


class Proxy:
    """One filter, source, reader or writer of the catalogue."""

    def __init__(self, group, element, xml_file):
        self.group = group
        # The server-manager name carries the prefix that keeps it apart from stock ParaView's
        # proxies (ImageReader, MeshQuality); pipeline files and the CLI use the short name.
        self.xml_name = element.get("name")
        self.name = self.xml_name[len(PREFIX):] if self.xml_name.startswith(PREFIX) else self.xml_name
        self.class_name = element.get("class")
        self.label = element.get("label", self.name)
        self.xml_file = xml_file
        self.is_writer = element.tag == "WriterProxy"
        self.properties = {}
        for child in element:
            if child.tag in _TYPES and child.get("information_only") != "1":
                p = Property(child)
                self.properties[p.name] = p
        self.output_ports = {}
        for i, port in enumerate(element.findall("OutputPort")):
            self.output_ports[port.get("name")] = int(port.get("index", i))
        doc = element.find("Documentation")
        self.short_help = doc.get("short_help", "") if doc is not None else ""
        self.long_help = doc.get("long_help", self.short_help) if doc is not None else ""
        self.documentation = " ".join(doc.text.split()) if doc is not None and doc.text else ""

    @property
    def inputs(self):
        return [p for p in self.properties.values() if p.kind == "input"]

    def __repr__(self):
        return "Proxy(%s -> %s)" % (self.name, self.class_name)


def default_xml_files():
    here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "servermanager")
    return sorted(glob.glob(os.path.join(here, "*.xml")))


def load(xml_files=None):
    """Return {short proxy name: Proxy} for every proxy of the server-manager XML files (the
    short name is the server-manager name without its "Anatomesh" prefix)."""
    proxies = {}
    for path in xml_files or default_xml_files():
        root = ET.parse(path).getroot()
        for group in root.iter("ProxyGroup"):
            for element in group:
                if element.tag in ("SourceProxy", "WriterProxy", "Proxy"):
                    proxy = Proxy(group.get("name"), element, path)
                    proxies[proxy.name] = proxy
    return proxies
