"""Read the tables of README.md that tests check against the code (``<!-- table: NAME -->``)."""
from __future__ import annotations

from pathlib import Path

README = Path(__file__).resolve().parent.parent / 'README.md'


def read_table(name: str) -> list[dict[str, str]]:
    """Return the rows of README table ``name`` as dicts by column header (backquotes removed)."""
    text = README.read_text()
    start = text.index(f'<!-- table: {name} -->')
    end = text.index(f'<!-- /table: {name} -->', start)
    lines = [ln.strip() for ln in text[start:end].splitlines()[1:] if ln.strip().startswith('|')]

    def cells(line: str) -> list[str]:
        parts = line.strip('|').replace('\\|', '\0').split('|')
        return [p.strip().replace('\0', '|').replace('`', '') for p in parts]

    header = cells(lines[0])
    return [dict(zip(header, cells(ln))) for ln in lines[2:]]
