"""The writers: text (Markdown, LaTeX, HTML, JSON, PDF), figures and plots from a Solution.
May import: steps, physics, problem and the leaves; never checking, homework, verifier or commands.
"""
