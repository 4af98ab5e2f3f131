#!/usr/bin/env python3
"""docs/typed/quick-start.md is true: its one file compiles with exactly the documented
compiler lines (and with clang++ in place of g++), and the checked and unchecked programs
print the documented output.

    check_quick_start.py <source-root> <work-dir> [compiler ...]

The page's commands say `-I safegi/typed/include`; the work directory gets a link
`safegi` to the source root so that they run as written."""
import pathlib
import re
import shutil
import subprocess
import sys


def blocks(text, language):
    return re.findall(r"```" + language + r"\n(.*?)```", text, flags=re.S)


def main():
    root, work = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2])
    compilers = sys.argv[3:] or ["g++", "clang++"]
    page = (root / "docs/typed/quick-start.md").read_text()
    source = blocks(page, "cpp")
    commands = [line for block in blocks(page, "sh") for line in block.splitlines() if line.startswith("g++ ")]
    outputs = [block for block in blocks(page, "text") if block.startswith("$ ./lighting\n")]
    if len(source) != 1 or len(commands) != 2 or len(outputs) != 1:
        sys.exit(f"quick-start.md: expected one cpp block, two g++ lines and one '$ ./lighting' output; found "
                 f"{len(source)}, {len(commands)}, {len(outputs)}")
    expected = outputs[0].split("\n", 1)[1]

    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    (work / "safegi").symlink_to(root)
    (work / "lighting.cpp").write_text(source[0])

    failures = []
    for compiler in compilers:
        for command in commands:
            line = compiler + command[len("g++"):]
            run = subprocess.run(line, shell=True, cwd=work, capture_output=True, text=True)
            if run.returncode != 0:
                failures.append(f"`{line}` failed:\n{run.stderr}")
                continue
            program = line.rsplit("-o ", 1)[1].strip()
            result = subprocess.run([str(work / program)], capture_output=True, text=True)
            if result.stdout != expected:
                failures.append(f"`{line}`: ./{program} printed\n{result.stdout!r}\nbut the page says\n{expected!r}")
            else:
                print(f"ok: {line}")
    if failures:
        sys.exit("\n".join(failures))


if __name__ == "__main__":
    main()
