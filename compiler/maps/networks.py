"""The network a plan is planned on, in both formats, converted once and kept in a cache.

    network = network_of("town.net.xml")     # Network(map, sha256, sumo=the map itself, opendrive=None)
    network = network_of("roads.xodr")       # sumo: netconvert's .net.xml of it (cached), opendrive: the map
    network = with_opendrive(network)        # opendrive: netconvert's .xodr of a SUMO map (cached)

Conversions are the only place sovarc runs netconvert on a map. Each is kept in a content-addressed
cache folder ($XDG_CACHE_HOME/sovarc/networks, else ~/.cache/sovarc/networks), as
`<map sha256>-<netconvert version hash>/<name>`: the same map bytes and the same netconvert give the
same file, which is written atomically, so concurrent runs share it. Targets read these files and
never convert anything themselves.

A SUMO network converted to OpenDRIVE keeps its coordinates (--offset.disable-normalization), so
plan points are OpenDRIVE points. netconvert's dated header comment and header date are replaced so
that the same SUMO version gives the same bytes. netconvert declares OpenDRIVE 1.4 but writes some
1.5 markup into it: a header <offset> (for a network with a geographic offset, e.g. any OSM import)
and 1.5 attributes on the outlines of crosswalks. Such a file is valid under no OpenDRIVE schema, so
the conversion is made what it says it is: the offset is kept inside a header
<userData code="offset"> (1.4 header user data may hold any markup), and the 1.5 outline attributes
are dropped. Road geometry is untouched.
"""

from __future__ import annotations

import hashlib
import os
import re
import tempfile
from dataclasses import replace
from pathlib import Path

from sovarc.compiler.fsutil import user_cache, write_atomic
from sovarc.compiler.maps.lefthand import MIRROR_VERSION, mirror_bytes, opendrive_keeps_left
from sovarc.compiler.maps.netconvert import convert_opendrive, netconvert_version, run_netconvert
from sovarc.compiler.plan import Network
from sovarc.dsl.errors import Diagnostic, InputError
from sovarc.dsl.span import Span

SUMO_SUFFIX = ".net.xml"
OPENDRIVE_SUFFIX = ".xodr"

_HEADER_COMMENT = re.compile(r"<!-- generated on .*?-->", re.DOTALL)
_HEADER_DATE = re.compile(r'(<header\b[^>]*?)\s+date="[^"]*"')
_HEADER = re.compile(r"<header\b.*?</header>", re.DOTALL)
_OFFSET = re.compile(r'(?<!<userData code="offset">)<offset\b[^>]*/>')  # one not yet kept as user data
# OpenDRIVE 1.5 attributes netconvert writes on crosswalk outlines: (the element's start tag, its 1.5 attributes).
_V15_ATTRIBUTES = tuple(
    (re.compile(rf"<{tag}\b[^>]*>"), re.compile(r"\s+(?:" + "|".join(names) + r')="[^"]*"'))
    for tag, names in (("outline", ("id", "fillType", "outer", "closed", "laneType")), ("cornerLocal", ("id",)))
)


def cache_dir() -> Path:
    return user_cache("networks")


def network_of(map_path: str | os.PathLike[str], sha256: str | None = None) -> Network:
    """The network of a `.net.xml` or `.xodr` map; an OpenDRIVE map is converted to SUMO (cached).

    `sha256` is the map file's, when the caller has read it already."""
    source = Path(map_path)
    digest = sha256 or _sha256(source)
    if _is(source, SUMO_SUFFIX):
        return Network(str(source), digest, str(source))
    if _is(source, OPENDRIVE_SUFFIX):
        return Network(str(source), digest, str(sumo_network(source, digest)), str(source))
    raise _input_error(source, "not a road network: expected a .net.xml or .xodr file")


def with_opendrive(network: Network) -> Network:
    """The network with its OpenDRIVE file: a SUMO map's conversion (cached) when it has none yet."""
    if network.opendrive is not None:
        return network
    return replace(network, opendrive=str(opendrive_network(Path(network.sumo), network.sha256, Path(network.map))))


def sumo_network(xodr: Path, sha256: str) -> Path:
    """The cached `.net.xml` netconvert makes of an OpenDRIVE file (made now if not cached yet)."""
    left = opendrive_keeps_left(xodr)
    target = _cached(sha256, xodr.name[: -len(OPENDRIVE_SUFFIX)] + ("-lht" if left else "") + SUMO_SUFFIX)
    if target.is_file():
        return target
    with tempfile.TemporaryDirectory(prefix="sovarc-net-") as tmp:
        made = Path(tmp) / target.name
        convert_opendrive(xodr, made, lefthand=left)
        return _store(target, made.read_bytes())


def mirrored_network(net: Path, sha256: str) -> Path:
    """The cached mirror image of a left-hand SUMO network (lefthand.py) whose map hashes to `sha256`
    (made now if not cached yet)."""
    target = _cached(sha256, f"{net.name[: -len(SUMO_SUFFIX)]}-mirror{MIRROR_VERSION}{SUMO_SUFFIX}")
    return target if target.is_file() else _store(target, mirror_bytes(net))


def opendrive_network(net: Path, sha256: str, named: Path | None = None) -> Path:
    """The cached OpenDRIVE 1.4 file of a SUMO network (made now if not cached yet).

    `named` is the map as the user gave it (default `net`): its name names the file and its header note."""
    name = (named or net).name
    base = name[: -len(SUMO_SUFFIX)] if name.lower().endswith(SUMO_SUFFIX) else name
    target = _cached(sha256, base + OPENDRIVE_SUFFIX)
    return target if target.is_file() else _store(target, _to_opendrive(net, name))


def _to_opendrive(net: Path, name: str) -> bytes:
    with tempfile.TemporaryDirectory(prefix="sovarc-xodr-") as tmp:
        out = Path(tmp) / "net.xodr"
        args = ["--sumo-net-file", str(net), "--opendrive-output", str(out), "--offset.disable-normalization", "true"]
        run_netconvert([*args, "--xml-validation", "never", "--no-warnings", "true"], net)
        text = out.read_text(encoding="utf-8")
    note = f"<!-- generated by {netconvert_version()} from {name} (sovarc) -->"
    text = _HEADER_COMMENT.sub(lambda _: note, text, count=1)
    text = _HEADER_DATE.sub(r"\1", text, count=1)
    return as_opendrive_14(text).encode("utf-8")


def as_opendrive_14(text: str) -> str:
    """netconvert's OpenDRIVE text without its OpenDRIVE 1.5 markup (see the module docstring)."""
    text = _HEADER.sub(lambda m: _OFFSET.sub(lambda o: f'<userData code="offset">{o[0]}</userData>', m[0]), text, 1)
    for start_tag, attributes in _V15_ATTRIBUTES:
        text = start_tag.sub(lambda m, a=attributes: a.sub("", m[0]), text)
    return text


def _cached(sha256: str, name: str) -> Path:
    tool = hashlib.sha256(netconvert_version().encode("utf-8")).hexdigest()[:12]
    return cache_dir() / f"{sha256}-{tool}" / name


def _store(target: Path, data: bytes) -> Path:
    """Write a conversion into the cache; where the cache cannot be written, into the temp folder."""
    try:
        write_atomic(target, data)
    except OSError:
        target = Path(tempfile.gettempdir()) / "sovarc-networks" / target.parent.name / target.name
        write_atomic(target, data)
    return target


def _is(source: Path, suffix: str) -> bool:
    return source.name.lower().endswith(suffix)


def _sha256(source: Path) -> str:
    try:
        return hashlib.sha256(source.read_bytes()).hexdigest()
    except OSError as e:
        raise _input_error(source, f"cannot read the map: {e.strerror}") from None


def _input_error(source: Path, message: str) -> InputError:
    return InputError(Diagnostic(message, Span.whole_file(str(source))))
