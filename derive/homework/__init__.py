"""Homework: variants of a problem, LMS exports (Moodle, PrairieLearn), handouts and the theory page.
May import: checking (its mistakes, for LMS feedback), writers, steps, physics, problem and the leaves; never verifier or commands.
"""
