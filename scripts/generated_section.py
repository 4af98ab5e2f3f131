"""A generated section of a documentation page: the text between two markers
that a script writes (--write) and ctest keeps current (--check)."""
import pathlib
import sys


def update(doc: pathlib.Path, begin: str, end: str, content: str, check: bool, regenerate: str) -> int:
    """Writes `content` between the markers of `doc`, or (check) returns 1 and says how to
    regenerate it when the page holds something else."""
    text = doc.read_text()
    if begin not in text or end not in text:
        sys.exit(f"{doc}: no {begin} … {end} markers")
    head, rest = text.split(begin, 1)
    old, tail = rest.split(end, 1)
    if not check:
        doc.write_text(head + begin + "\n" + content + end + tail)
        return 0
    if old == "\n" + content:
        return 0
    sys.stdout.write(f"{doc}: the generated section is stale; run {regenerate}\n")
    sys.stdout.write(content)
    return 1
