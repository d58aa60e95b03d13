"""The verifier's answer: the failing lines, each with its rule and reason, and what was checked."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Failure:
    """One wrong line: where it is, what it says, the rule it breaks and why."""

    line: int
    text: str
    rule: str
    reason: str
    scope: str = ""

    def format(self) -> str:
        where = f"line {self.line}" if self.line else "page"
        part = f" [{self.scope}]" if self.scope else ""
        text = f"\n    {self.text}" if self.text else ""
        return f"{where}{part}: {self.rule}: {self.reason}{text}"


@dataclass
class VerifyReport:
    """All failures of one page, and the count of lines and relations checked."""

    failures: list[Failure] = field(default_factory=list)
    lines: int = 0
    relations: int = 0
    unchecked: list[tuple[int, str]] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """True when no line failed."""
        return not self.failures

    def by_rule(self) -> Counter[str]:
        return Counter(f.rule for f in self.failures)

    def format(self) -> str:
        """Each failing line with its reason, then a one-line summary."""
        out = [f.format() for f in self.failures]
        verdict = "every line holds" if self.ok else f"{len(self.failures)} failing"
        out.append(f"verify: {self.lines} lines, {self.relations} relations checked: {verdict}")
        return "\n".join(out)
