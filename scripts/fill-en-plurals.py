#!/usr/bin/env python3
"""Fills the English plural forms in translations/imudesk_en.ts.

Source texts write plurals as "%n byte(s)"; English has two forms: the singular drops
"(s)", the plural keeps the "s" ("%n entry(ies)" -> "entry" / "entries"). Entries that
already have both forms are left as they are. Run after `ninja imudesk_lupdate`.
"""
import re
import sys
import xml.etree.ElementTree as ET

path = sys.argv[1] if len(sys.argv) > 1 else "translations/imudesk_en.ts"
tree = ET.parse(path)
filled = 0
for message in tree.iter("message"):
    if message.get("numerus") != "yes":
        continue
    source = message.findtext("source") or ""
    translation = message.find("translation")
    forms = translation.findall("numerusform")
    if len(forms) == 2 and all((f.text or "").strip() for f in forms) and translation.get("type") != "unfinished":
        continue
    singular = re.sub(r"(\w+)\(ies\)", lambda m: m.group(1) + "y", source)
    singular = singular.replace("(s)", "").replace("(es)", "")
    plural = re.sub(r"(\w+)\(ies\)", lambda m: m.group(1) + "ies", source)
    plural = plural.replace("(s)", "s").replace("(es)", "es")
    for f in forms:
        translation.remove(f)
    for text in (singular, plural):
        f = ET.SubElement(translation, "numerusform")
        f.text = text
    translation.attrib.pop("type", None)
    filled += 1
with open(path, "wb") as out:
    out.write(b'<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n')
    tree.write(out, encoding="utf-8", xml_declaration=False)
print(f"{path}: filled {filled} plural message(s)")
