"""Front ends: everything that turns something else (a report, ground truth) into scenario IR."""
