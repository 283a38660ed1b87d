"""Pure numerical core of freestand: SI floats and numpy arrays only.

Nothing in this package prints, reads or writes files, or plots.
"""
