"""Every ```python block of docs/python.md and README.md runs, from the repository's root.

docs_run.rs (cargo test) runs the documents' TOML and `$ massprop` lines;
the Python blocks need the installed wheel, so they run here. A block
marked `<!-- docs-test: skip REASON -->` on the line before its fence is
not run, as there.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from conftest import REPO

DOCUMENTS = [REPO / "docs" / "python.md", REPO / "README.md"]


def _python_blocks(path: Path) -> list[tuple[str, str]]:
    lines = path.read_text(encoding="utf-8").splitlines()
    blocks, i = [], 0
    while i < len(lines):
        if lines[i].strip() == "```python":
            start = i
            i += 1
            while lines[i].strip() != "```":
                i += 1
            skipped = start > 0 and re.match(r"\s*<!-- docs-test: skip \S", lines[start - 1])
            if not skipped:
                blocks.append(
                    (f"{path.relative_to(REPO)}:{start + 1}", "\n".join(lines[start + 1 : i]))
                )
        i += 1
    return blocks


BLOCKS = [block for path in DOCUMENTS for block in _python_blocks(path)]


def test_the_python_page_has_examples_to_run() -> None:
    assert sum(1 for where, _ in BLOCKS if where.startswith("docs")) >= 4


@pytest.mark.parametrize("code", [code for _, code in BLOCKS], ids=[where for where, _ in BLOCKS])
def test_the_python_block_runs(code: str, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(REPO)
    exec(compile(code, "<block>", "exec"), {"__name__": "__docs__"})
