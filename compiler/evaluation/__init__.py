"""Evaluations of the compiler against ground truth (`sovarc eval ...`)."""
