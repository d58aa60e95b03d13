"""One module per chain stage type: each solves its stage and returns its record."""
