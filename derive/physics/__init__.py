"""The physics: equations (1)-(4) of the notes, solved in closed form, and the stages of a chain, as data (no text).
May import: problem and the leaves (errors, symbols, numbers, escape, resources, fileio).
"""
