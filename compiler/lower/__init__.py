"""Constraint lowering: a scenario on one site of a map, solved with Z3 (the paper's Groups 1-5)."""
