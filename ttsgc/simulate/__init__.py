"""Proving scenes: read a file into a Plan, play it (players/), judge the traces (judge.py)."""
