"""sovarc's back ends: each turns a Plan into files a simulator or tool runs, and judges them.

contract.py   the Target protocol every back end implements, and how verdicts are written
registry.py   name -> Target: `registry.get("sumo")`, `registry.names()`, `registry.register(obj)`
verdict.py    Verdict and Finding, the same shape for every target
sumo/ openscenario/ fmu/   the built-in targets, each exporting TARGET

A new target is one subpackage and one registry line.
"""
