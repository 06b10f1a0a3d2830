"""Byte-stable XML text: fixed attribute order, fixed number formats, no dates, no paths."""

from __future__ import annotations

from collections.abc import Sequence

HEADER = '<?xml version="1.0" encoding="UTF-8"?>\n'
XSD_NS = 'xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"'

Attrs = Sequence[tuple[str, str]]
# saxutils.escape with the quote, in one pass (an FCD file has a few hundred thousand values)
_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;"})


def num(value: float, digits: int) -> str:
    """A fixed-point number; never '-0.00'."""
    text = f"{value:.{digits}f}"
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text


def attrs(pairs: Attrs) -> str:
    return "".join(f' {key}="{value.translate(_ESCAPES)}"' for key, value in pairs)


def empty(tag: str, pairs: Attrs, indent: int) -> str:
    return f"{' ' * indent}<{tag}{attrs(pairs)}/>\n"


def element(tag: str, pairs: Attrs, children: Sequence[str], indent: int) -> str:
    """An element with child lines (already indented); self-closing when there are none."""
    if not children:
        return empty(tag, pairs, indent)
    pad = " " * indent
    return f"{pad}<{tag}{attrs(pairs)}>\n{''.join(children)}{pad}</{tag}>\n"


def comment(text: str) -> str:
    return f"<!-- {text.replace('--', '- -')} -->\n"


def root(tag: str, schema: str, children: Sequence[str], note: str) -> str:
    """A whole document: declaration, one comment, the root with SUMO's schema location."""
    location = f'xsi:noNamespaceSchemaLocation="http://sumo.dlr.de/xsd/{schema}"'
    return f"{HEADER}\n{comment(note)}\n<{tag} {XSD_NS} {location}>\n{''.join(children)}</{tag}>\n"


def params(pairs: Sequence[tuple[str, str]], indent: int) -> list[str]:
    return [empty("param", (("key", key), ("value", value)), indent) for key, value in pairs]
