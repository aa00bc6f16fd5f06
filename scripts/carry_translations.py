#!/usr/bin/env python3
"""Carries finished translations over to messages that moved to another context.

Usage: carry_translations.py OLD.ts NEW.ts
NEW.ts (as lupdate just wrote it) is rewritten in place: every unfinished message whose
source text (and disambiguation comment) has a finished translation in OLD.ts, in any
context, takes that translation. A string that moved from MainWindow to a feature class
keeps its Danish; a string that is new stays unfinished for a translator. Prints what it
carried and what is left unfinished.
"""
import sys
import xml.etree.ElementTree as ET


def key(message):
    comment = message.find("comment")
    return (message.findtext("source"), comment.text if comment is not None else None)


def main(old_path, new_path):
    finished = {}
    for message in ET.parse(old_path).getroot().iter("message"):
        translation = message.find("translation")
        if translation is not None and translation.get("type") not in ("unfinished", "obsolete", "vanished"):
            finished.setdefault(key(message), translation)
    tree = ET.parse(new_path)
    carried, left = 0, []
    for context in tree.getroot().iter("context"):
        for message in context.iter("message"):
            translation = message.find("translation")
            if translation is None or translation.get("type") != "unfinished":
                continue
            found = finished.get(key(message))
            if found is None:
                left.append(f"{context.findtext('name')}: {message.findtext('source')}")
                continue
            message.remove(translation)
            copy = ET.fromstring(ET.tostring(found))
            copy.tail = translation.tail
            message.append(copy)
            carried += 1
    with open(new_path, "wb") as out:
        out.write(b'<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n')
        tree.write(out, encoding="utf-8", xml_declaration=False)
        out.write(b"\n")
    print(f"carried {carried} translations; {len(left)} left unfinished")
    for line in left:
        print("  unfinished:", line)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
