"""Printing: the c/s notation (`notation`), SymPy printer subclasses that write it (`printers`),
whole matrices, tables and legends (`render`), and rich display in notebooks (`display`)."""
