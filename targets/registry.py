"""The targets sovarc knows, by name: the one way the compiler reaches a back end.

    registry.names()          # ('sumo', 'openscenario', 'fmu'): the -t choices, in this order
    registry.get("sumo")      # the object implementing targets.contract.Target
    registry.register(obj)    # one more at run time (a plug-in, a test's tiny target)

A new target is one subpackage and one line in BUILTIN. Importing a target's subpackage is light:
each loads its simulator's bindings (libsumo, fmpy, ASAM's checker) only when it runs.
"""

from __future__ import annotations

from sovarc.targets import fmu, openscenario, sumo
from sovarc.targets.contract import Flag, Target, flags

BUILTIN: tuple[Target, ...] = (sumo.TARGET, openscenario.TARGET, fmu.TARGET)

_TARGETS: dict[str, Target] = {t.name: t for t in BUILTIN}


def names() -> tuple[str, ...]:
    return tuple(_TARGETS)


def get(name: str) -> Target:
    """The target of that name; KeyError naming the known ones otherwise."""
    try:
        return _TARGETS[name]
    except KeyError:
        raise KeyError(f"unknown target {name!r}; choose from {', '.join(_TARGETS)}") from None


def register(target: Target, *, replace: bool = False) -> Target:
    """Add a target (after the built-in ones); a name already taken needs `replace=True`."""
    if not isinstance(target, Target):
        raise TypeError(f"{target!r} does not implement the target contract (targets/contract.py)")
    if target.name in _TARGETS and not replace:
        raise ValueError(f"a target named {target.name!r} is already registered")
    _TARGETS[target.name] = target
    return target


def unregister(name: str) -> None:
    """Remove a target added with register (a built-in one stays)."""
    if name in {t.name for t in BUILTIN}:
        raise ValueError(f"{name!r} is a built-in target")
    _TARGETS.pop(name, None)


def all_flags() -> list[Flag]:
    """Every registered target's command-line flags, in registry order; one per flag (the first declares it)."""
    seen: dict[str, Flag] = {}
    for target in _TARGETS.values():
        for flag in flags(target):
            seen.setdefault(flag.flag, flag)
    return list(seen.values())
