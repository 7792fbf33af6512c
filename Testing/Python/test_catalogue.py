"""The server-manager XML (one catalogue for ParaView, the pipeline runner and the docs) and the
C++ classes cannot drift: every proxy's class exists in the Python package, and every property's
Set-method exists and accepts the XML default (or, without one, a value of the right type)."""
import unittest

import anatomesh
from anatomesh import catalogue


class CatalogueMatchesClasses(unittest.TestCase):
    def test_every_proxy_and_property(self):
        proxies = catalogue.load()
        self.assertIn("ThoraxPhantomSource", proxies)
        self.assertIn("ImageReader", proxies)
        self.assertIn("MeditWriter", proxies)
        self.assertIn("SnakeSegmentation", proxies)
        self.assertIn("MorphologyCleaning", proxies)
        for name, proxy in proxies.items():
            cls = getattr(anatomesh, proxy.class_name, None)
            self.assertIsNotNone(cls, "%s: class %s missing" % (name, proxy.class_name))
            obj = cls()
            for prop in proxy.properties.values():
                if prop.kind == "input":
                    self.assertTrue(hasattr(obj, prop.command), (name, prop.name))
                    continue
                setter = getattr(obj, prop.command, None)
                self.assertIsNotNone(setter, "%s.%s: no method %s" % (name, prop.name, prop.command))
                if prop.repeat_command:
                    if prop.use_index:  # ParaView's indexed form
                        self.assertTrue(prop.set_number_command, (name, prop.name))
                        getattr(obj, prop.set_number_command)(1)
                        setter(0, *([1] * prop.per_command))
                        continue
                    self.assertTrue(prop.clean_command, (name, prop.name))
                    getattr(obj, prop.clean_command)()
                    setter(*([1] * prop.per_command))
                    continue
                if prop.kind == "string":
                    value = [prop.defaults[0] if prop.defaults else "x"]
                else:
                    conv = int if prop.kind == "int" else float
                    value = [conv(v) for v in (prop.defaults or ["1"] * prop.number_of_elements)]
                    self.assertEqual(len(value), prop.number_of_elements, (name, prop.name))
                setter(*value)
                getter = getattr(obj, "G" + prop.command[1:], None)
                if getter is not None and prop.kind != "string":
                    got = getter()
                    got = list(got) if isinstance(got, (tuple, list)) else [got]
                    self.assertEqual([float(g) for g in got], [float(v) for v in value], (name, prop.name))
            self.assertTrue(proxy.short_help, "%s has no documentation" % name)
            for prop in proxy.properties.values():
                self.assertTrue(prop.documentation, "%s.%s has no documentation" % (name, prop.name))

    def test_xml_defaults_equal_the_classes_defaults(self):
        """ParaView (which applies the XML defaults) and Python or the pipeline runner (which start
        from the class's own) must compute the same thing when nothing is set."""
        checked, mismatches = 0, []
        for name, proxy in catalogue.load().items():
            obj = getattr(anatomesh, proxy.class_name)()
            for prop in proxy.properties.values():
                if (prop.kind == "input" or prop.defaults is None or prop.repeat_command
                        or not prop.command.startswith("Set")):
                    continue
                getter = getattr(obj, "G" + prop.command[1:], None)
                if getter is None:
                    continue
                try:
                    got = getter()
                except TypeError:  # a getter that needs an argument (e.g. an indexed value)
                    continue
                checked += 1
                if prop.kind == "string":
                    same = (got or "") == (prop.defaults[0] if prop.defaults else "")
                else:
                    got = list(got) if isinstance(got, (tuple, list)) else [got]
                    same = len(got) == len(prop.defaults) and all(
                        abs(float(g) - float(d)) <= 1e-12 * max(1.0, abs(float(d))) for g, d in zip(got, prop.defaults))
                if not same:
                    mismatches.append("%s.%s: XML %s, class %s" % (name, prop.name, " ".join(prop.defaults), got))
        self.assertGreater(checked, 100)
        self.assertEqual(mismatches, [])

    def test_repeatable_defaults_equal_the_classes_defaults(self):
        """A repeatable property (AddX, one value group a call) keeps its default list in the class;
        the class reads it back through GetNumberOfXs() and GetX(i), which every repeatable property
        with an XML default must have, so the two lists cannot drift apart."""
        checked, problems = 0, []
        for name, proxy in catalogue.load().items():
            obj = getattr(anatomesh, proxy.class_name)()
            for prop in proxy.properties.values():
                if not prop.repeat_command or prop.defaults is None:
                    continue
                if prop.use_index:  # SetNumberOfXs + SetX(i, ...): read back by GetNumberOfXs and GetX(i)
                    count_name, get_name = "G" + prop.set_number_command[1:], "G" + prop.command[1:]
                else:  # AddX: GetNumberOfXs and GetX(i)
                    item = prop.command[len("Add"):]
                    count_name = "GetNumberOf" + (item[:-1] + "ies" if item.endswith("y") else item + "s")
                    get_name = "Get" + item
                count, get = getattr(obj, count_name, None), getattr(obj, get_name, None)
                if count is None or get is None:
                    problems.append("%s.%s: no %s/%s" % (name, prop.name, count_name, get_name))
                    continue
                got = []
                for i in range(count()):
                    value = get(i)
                    got.extend(value if isinstance(value, (tuple, list)) else [value])
                checked += 1
                if [float(g) for g in got] != [float(d) for d in prop.defaults]:
                    problems.append("%s.%s: XML %s, class %s" % (name, prop.name, prop.defaults, got))
        self.assertGreaterEqual(checked, 6)
        self.assertEqual(problems, [])

    def test_output_ports(self):
        proxies = catalogue.load()
        src = anatomesh.amThoraxPhantomSource()
        self.assertEqual(src.GetNumberOfOutputPorts(), len(proxies["ThoraxPhantomSource"].output_ports))


if __name__ == "__main__":
    unittest.main()
