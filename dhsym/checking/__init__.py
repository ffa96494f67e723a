"""Checking: equality by algebra and by numbers (`verify`), and comparison with what a lecture
printed (`errata`)."""
