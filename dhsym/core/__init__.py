"""The math: elementary transforms and DH rows (`transforms`), chains and their products
(`chain`), the contraction into textbook form (`simplify`) and its time budget (`budget`)."""
