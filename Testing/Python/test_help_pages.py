"""The plugin's Help pages (ParaView's Help > Anatomesh, compiled from the server-manager XML into
the Qt help file the plugin embeds) have one page per proxy, with its description and every
property's documentation and default. Skipped when the build made no help file (no Qt tools)."""
import html
import os
import re
import sqlite3
import unittest
import zlib

from anatomesh import catalogue

QCH = os.environ.get("ANATOMESH_HELP_QCH", "")


def _text(page):
    return " ".join(html.unescape(re.sub(r"<[^>]+>", " ", page)).split())


@unittest.skipUnless(QCH and os.path.isfile(QCH), "the plugin was built without Help pages")
class HelpPages(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        # A .qch is an SQLite database; each file's data is qCompress'ed (4-byte size, then zlib).
        with sqlite3.connect("file:%s?mode=ro" % QCH, uri=True) as db:
            rows = db.execute("SELECT n.Name, d.Data FROM FileNameTable n JOIN FileDataTable d ON n.FileId = d.Id")
            cls.pages = {name: zlib.decompress(data[4:]).decode("utf-8") for name, data in rows if name}

    def test_one_page_per_proxy_with_its_documentation(self):
        proxies = catalogue.load()
        self.assertGreater(len(proxies), 20)
        for proxy in proxies.values():
            name = "%s.%s.html" % (proxy.group, proxy.xml_name)
            self.assertIn(name, self.pages)
            text = _text(self.pages[name])
            self.assertIn(proxy.label, text, name)
            self.assertIn(_text(proxy.long_help), text, name)
            self.assertIn(_text(proxy.documentation), text, name)
            for prop in proxy.properties.values():
                self.assertIn(_text(prop.documentation), text, "%s: %s" % (name, prop.name))
                if prop.defaults and not prop.repeat_command and prop.enumeration is None:
                    self.assertIn(" ".join(prop.defaults), text, "%s: %s default" % (name, prop.name))

    def test_reader_and_writer_indexes(self):
        self.assertIn("Readers.html", self.pages)
        self.assertIn("Writers.html", self.pages)
        self.assertIn("AnatomeshImageReader", self.pages["Readers.html"])
        self.assertIn("AnatomeshGmshWriter", self.pages["Writers.html"])


if __name__ == "__main__":
    unittest.main()
