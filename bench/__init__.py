"""Benchmarks, run side by side with their baselines: ``python -m bench``."""
