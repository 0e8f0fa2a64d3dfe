"""Maintenance tools of the plcmotion checkout (run from its root, e.g. ``PYTHONPATH=src python -m tools.gen_s7t_docs``).

A package so that the generators share their helpers (``tools.s7t_pages``); tests import them as ``tools.<name>``.
"""
