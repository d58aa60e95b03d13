"""One module per chain stage type: each solves its stage and returns its record.
May import: the rest of physics, problem and the leaves.
"""
