#!/usr/bin/env python3
"""safegi-lsp: diagnostics latency on didChange, hover latency, server CPU time.

Drives build/bin/safegi-lsp as an editor does (JSON-RPC over pipes) on each
example shader: opens it, then sends N full-text didChange notifications
(alternately the shader with and without its `* cosTheta`-style fix, so every
change recompiles and alternates between an error and none) and times each
until its publishDiagnostics arrives; then N hover requests on one name. The
server's CPU time (utime + stime from /proc) over the N changes gives the CPU
per change, which load on a shared machine does not inflate. Baseline in the
same run: one `safeglslc` process on the same text (what an editor without a
server would run on save), interleaved with the changes.

Instruction counts (callgrind, which load does not change) give the same
comparison without the noise: a session of K changes minus a session of none,
per change, for the whole server (JSON, framing, diagnostics) and for the
compile inside it (`compile_here`, with the analysis kept and the checker's
symbols recorded), against the compile inside one `safeglslc` run.
"""
from __future__ import annotations

import json
import os
import re
import tempfile
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
import harness as h  # noqa: E402

SHADERS = ["point_light.sgl.frag", "area_light.sgl.frag", "shadow_map.sgl.frag", "transform.sgl.vert"]


class Server:
    def __init__(self, command: list[str]):
        self.p = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        self.next_id = 1

    def send(self, message: dict) -> None:
        body = json.dumps(message).encode()
        self.p.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.p.stdin.flush()

    def receive(self) -> dict:
        header = b""
        while not header.endswith(b"\r\n\r\n"):
            byte = self.p.stdout.read(1)
            if not byte:
                raise SystemExit("bench: safegi-lsp closed its output")
            header += byte
        length = int(header.split(b"Content-Length:")[1].split(b"\r\n")[0])
        return json.loads(self.p.stdout.read(length))

    def request(self, method: str, params: dict) -> dict:
        self.next_id += 1
        self.send({"jsonrpc": "2.0", "id": self.next_id, "method": method, "params": params})
        while True:
            m = self.receive()
            if m.get("id") == self.next_id and "method" not in m:
                return m

    def notify(self, method: str, params: dict) -> None:
        self.send({"jsonrpc": "2.0", "method": method, "params": params})

    def diagnostics(self) -> dict:
        while True:
            m = self.receive()
            if m.get("method") == "textDocument/publishDiagnostics":
                return m["params"]

    def cpu_seconds(self) -> float:
        fields = Path(f"/proc/{self.p.pid}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    def close(self) -> None:
        self.request("shutdown", {})
        self.notify("exit", {})
        self.p.wait(timeout=10)


def broken(text: str, path: Path, safeglslc: str) -> str:
    """The shader with one annotation mistake that safeglslc rejects: a dimension changed in a declaration."""
    for good, bad in (("float<proj>", "float<angle>"), ("spectrum<radiance>", "spectrum<irradiance>"),
                      ("float<length>", "float<time>"), ("point<world>", "point<object>")):
        if good not in text:
            continue
        candidate = text.replace(good, bad, 1)
        stage = path.suffix.lstrip(".")
        if subprocess.run([safeglslc, "-S", stage, "-"], input=candidate, text=True, capture_output=True).returncode == 1:
            return candidate
    raise SystemExit(f"bench: no annotation mistake found for {path.name}")


def framed(messages: list[dict]) -> bytes:
    out = b""
    for m in messages:
        body = json.dumps(m).encode()
        out += b"Content-Length: %d\r\n\r\n" % len(body) + body
    return out


def session(uri: str, texts: list[str], changes: int) -> bytes:
    """initialize, didOpen of texts[1], `changes` full-text changes alternating texts, shutdown, exit."""
    messages = [{"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}},
                {"jsonrpc": "2.0", "method": "textDocument/didOpen",
                 "params": {"textDocument": {"uri": uri, "languageId": "glsl", "version": 1, "text": texts[1]}}}]
    for i in range(changes):
        messages.append({"jsonrpc": "2.0", "method": "textDocument/didChange",
                         "params": {"textDocument": {"uri": uri, "version": i + 2}, "contentChanges": [{"text": texts[i % 2]}]}})
    messages += [{"jsonrpc": "2.0", "id": 2, "method": "shutdown"}, {"jsonrpc": "2.0", "method": "exit"}]
    return framed(messages)


def callgrind(command: list[str], stdin: bytes = b"", inside: str | None = None) -> int:
    """Instructions of `command` fed `stdin` (all, or only under a function matching `inside`)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "callgrind.out"
        toggle = [f"--toggle-collect={inside}"] if inside else []
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", *toggle, *command], input=stdin,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for line in out.read_text().splitlines():
            match = re.match(r"^(?:summary|totals):\s+(\d+)", line)
            if match:
                return int(match.group(1))
    raise RuntimeError(f"no instruction total for {command}")


def main() -> None:
    changes = 20 if h.quick() else 200
    lsp = str(h.binary("safegi-lsp"))
    safeglslc = str(h.binary("safeglslc"))
    server = Server([lsp])
    server.request("initialize", {"capabilities": {}})
    server.notify("initialized", {})
    rows = []
    for name in SHADERS:
        path = h.ROOT / "examples" / "shaders" / name
        text = path.read_text()
        uri = path.resolve().as_uri()
        server.notify("textDocument/didOpen", {"textDocument": {"uri": uri, "languageId": "glsl", "version": 1, "text": text}})
        assert server.diagnostics()["diagnostics"] == [], name
        latencies, baseline = [], []
        texts = [broken(text, path, safeglslc), text]
        cpu_before = server.cpu_seconds()
        for i in range(changes):
            start = time.perf_counter()
            server.notify("textDocument/didChange", {"textDocument": {"uri": uri, "version": i + 2},
                                                     "contentChanges": [{"text": texts[i % 2]}]})
            published = server.diagnostics()
            latencies.append(time.perf_counter() - start)
            assert (len(published["diagnostics"]) > 0) == (i % 2 == 0), (name, published)
            if i % 10 == 0:  # interleaved, fewer: a process start is slower than a change
                start = time.perf_counter()
                subprocess.run([safeglslc, str(path)], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                baseline.append(time.perf_counter() - start)
        cpu = (server.cpu_seconds() - cpu_before) / changes
        # Hover on the name the first uniform declares.
        lines = text.split("\n")
        line = next(i for i, l in enumerate(lines) if l.startswith("uniform "))
        character = lines[line].index(";") - 1
        hovers = []
        for _ in range(changes):
            start = time.perf_counter()
            reply = server.request("textDocument/hover", {"textDocument": {"uri": uri},
                                                          "position": {"line": line, "character": character}})
            hovers.append(time.perf_counter() - start)
        assert reply.get("result"), (name, reply)
        lat = statistics.median(latencies) * 1e3
        base = statistics.median(baseline) * 1e3
        rows.append([name, f"{text.count(chr(10))}", f"{lat:.2f} ({min(latencies) * 1e3:.2f}–{max(latencies) * 1e3:.2f})",
                     f"{cpu * 1e3:.2f}", f"{statistics.median(hovers) * 1e3:.3f}", f"{base:.2f}", f"{lat / base:.2f}"])
    server.close()
    # Instruction counts: K changes minus none, per change.
    k = 10
    counts = []
    for name in SHADERS:
        path = h.ROOT / "examples" / "shaders" / name
        text = path.read_text()
        texts = [broken(text, path, safeglslc), text]
        uri = path.resolve().as_uri()
        # The first compile of a process also builds the built-in signature
        # library for the vocabulary (then cached): safeglslc's one compile and
        # the server's didOpen are both such cold compiles, the changes warm ones.
        plain = callgrind([safeglslc, str(path)], inside="*compile_here*")
        opened = callgrind([lsp], session(uri, texts, 0), "*compile_here*")
        compile_part = (callgrind([lsp], session(uri, texts, k), "*compile_here*") - opened) / k
        whole = (callgrind([lsp], session(uri, texts, k)) - callgrind([lsp], session(uri, texts, 0))) / k
        counts.append([name, f"{plain / 1e6:.2f}", f"{opened / 1e6:.2f}", h.ratio(opened, plain),
                       f"{compile_part / 1e6:.2f}", f"{whole / 1e6:.2f}"])
    out = "## safegi-lsp: diagnostics on didChange, hover\n\n"
    out += (f"{changes} full-text `didChange` notifications per shader, alternating a one-word annotation mistake and "
            "the original text, each timed until its `publishDiagnostics` arrives (median, min–max); the server's "
            "CPU time (utime + stime from /proc) per change; hover round trips (on the first uniform's name); and, interleaved, `safeglslc` on "
            f"the same file as one process per check. {h.machine_line()}. Wall times on a shared machine mostly "
            "measure the others: the CPU column is the one that does not move with load.\n\n")
    out += h.table(["shader", "lines", "didChange → diagnostics, ms", "server CPU per change, ms", "hover, ms",
                    "safeglslc process, ms", "ratio to safeglslc"], rows)
    out += ("\nInstructions (callgrind; load does not change them), in millions. Cold compiles (the first of a "
            "process, which also builds the built-in signature library once): the one inside a `safeglslc` run "
            "against the server's `didOpen`, which keeps the analysis and records the checker's symbols. Warm: "
            f"per change, from a session of {k} changes minus one of none, the compile alone and the whole "
            "server (JSON, framing, diagnostics; half the changes have one to render):\n\n")
    out += h.table(["shader", "safeglslc compile (cold)", "server didOpen compile (cold)", "ratio",
                    "server compile per change (warm)", "whole server per change"], counts)
    h.write_section("lsp", out)


if __name__ == "__main__":
    main()
