"""Checking: equality by algebra and by numbers (`verify`), comparison with what a lecture
printed (`errata`), and the kind of each erratum, the lecture's or the transcript's (`kinds`)."""
