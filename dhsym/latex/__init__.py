"""LaTeX documents: slides, article and snippet (`document`), what they show (`sections`), how
math is set on a line (`layout`), TeX widths (`width`) and beamer frame packing (`packing`)."""
