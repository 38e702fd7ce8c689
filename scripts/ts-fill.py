#!/usr/bin/env python3
"""Lists or fills the unfinished entries of a Qt .ts file.

  ts-fill.py list FILE.ts                 prints a JSON object {source: ""} of unfinished entries
  ts-fill.py fill FILE.ts MAP.json        fills unfinished entries from {source: translation}
                                          (numerus entries take a list of forms)

Only entries marked unfinished are touched; sources missing from the map stay unfinished.
The file is written back by ElementTree: run the lupdate target afterwards, which restores
Qt's own layout (otherwise every line of the file shows as changed).
"""
import json
import sys
import xml.etree.ElementTree as ET


def unfinished(tree):
    for message in tree.iter("message"):
        translation = message.find("translation")
        if translation is not None and translation.get("type") == "unfinished":
            yield message, translation


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("list", "fill"):
        sys.exit(__doc__)
    path = sys.argv[2]
    tree = ET.parse(path)
    if sys.argv[1] == "list":
        out = {m.findtext("source"): "" for m, _ in unfinished(tree)}
        json.dump(out, sys.stdout, ensure_ascii=False, indent=1)
        print()
        return
    mapping = json.load(open(sys.argv[3], encoding="utf-8"))
    filled = left = 0
    for message, translation in unfinished(tree):
        text = mapping.get(message.findtext("source"))
        if not text:
            left += 1
            continue
        if message.get("numerus") == "yes":
            forms = text if isinstance(text, list) else [text]
            for f in translation.findall("numerusform"):
                translation.remove(f)
            for form in forms:
                ET.SubElement(translation, "numerusform").text = form
        else:
            translation.text = text
        del translation.attrib["type"]
        filled += 1
    with open(path, "wb") as f:
        f.write(b'<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n')
        tree.write(f, encoding="utf-8", xml_declaration=False)
    print(f"{path}: filled {filled}, still unfinished {left}")


main()
