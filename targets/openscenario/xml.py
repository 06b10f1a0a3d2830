"""Building and writing XML with lxml, byte for byte the same for the same input."""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

from lxml import etree

Attr = str | float | int | bool

# Digits kept in the file: millimetres, milliradians/10, centiseconds/100.
LENGTH_DIGITS = 3
ANGLE_DIGITS = 4
TIME_DIGITS = 4


def num(value: float, digits: int = LENGTH_DIGITS) -> str:
    """A float in its shortest fixed form: 12.5, 0, -3.25 (never '-0', never an exponent)."""
    if not math.isfinite(value):
        raise ValueError(f"not a finite number: {value}")
    text = f"{round(value, digits):.{digits}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _text(value: Attr) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return num(value)
    return str(value)


def el(tag: str, attrs: Mapping[str, Attr] | None = None, *children: etree._Element | None) -> etree._Element:
    """An element with attributes in the given order and the children that are not None."""
    node = etree.Element(tag)
    for key, value in (attrs or {}).items():
        node.set(key, _text(value))
    node.extend(c for c in children if c is not None)
    return node


def sub(parent: etree._Element, tag: str, attrs: Mapping[str, Attr] | None = None) -> etree._Element:
    child = el(tag, attrs)
    parent.append(child)
    return child


def comment(text: str) -> etree._Comment:
    # '--' may not occur inside an XML comment.
    return etree.Comment(" " + text.replace("--", "- -") + " ")


def to_bytes(root: etree._Element, leading: Iterable[etree._Comment] = ()) -> bytes:
    """The document with an XML declaration, comments before the root, indented by two spaces."""
    tree = etree.ElementTree(root)
    for note in leading:
        root.addprevious(note)
    etree.indent(tree, space="  ")
    return b'<?xml version="1.0" encoding="UTF-8"?>\n' + etree.tostring(tree, encoding="UTF-8", pretty_print=True)
