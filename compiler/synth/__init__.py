"""Trajectory synthesis: OMPL paths, TOPP-RA speed limits and Ruckig timing."""
