#!/usr/bin/env python3
"""Prints a real safegi-lsp session on light.sgl.frag, message by message, as
docs/editor.md shows it (client → server, server ← client):

    python3 lsp/editors/transcript.py build/bin/safegi-lsp

initialize (offering UTF-8 positions), didOpen of the shader with its cosine
forgotten, the diagnostic, an incremental didChange that adds `* cosTheta`,
hover, definition, completion in `point<`, shutdown and exit.
"""
import json
import subprocess
import sys
from pathlib import Path

server = subprocess.Popen([sys.argv[1]], stdin=subprocess.PIPE, stdout=subprocess.PIPE)


def show(arrow, message):
    print(arrow, json.dumps(message, ensure_ascii=False))


def send(message):
    show("→", message)
    body = json.dumps(message).encode()
    server.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
    server.stdin.flush()


def receive():
    header = b""
    while not header.endswith(b"\r\n\r\n"):
        header += server.stdout.read(1)
    length = int(header.split(b":")[1].split(b"\r\n")[0])
    show("←", json.loads(server.stdout.read(length)))


path = Path(__file__).resolve().parent / "light.sgl.frag"
uri = path.as_uri()
document = {"uri": uri}
send({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {
    "processId": None, "rootUri": path.parent.as_uri(),
    "capabilities": {"general": {"positionEncodings": ["utf-8", "utf-16"]},
                     "textDocument": {"publishDiagnostics": {"relatedInformation": True},
                                      "hover": {"contentFormat": ["markdown"]}}}}})
receive()
send({"jsonrpc": "2.0", "method": "initialized", "params": {}})
send({"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
    "uri": uri, "languageId": "glsl", "version": 1, "text": path.read_text()}}})
receive()
send({"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": {"uri": uri, "version": 2},
      "contentChanges": [{"range": {"start": {"line": 14, "character": 39}, "end": {"line": 14, "character": 39}},
                          "text": " * cosTheta"}]}})
receive()
for request_id, method, line, character in ((2, "hover", 14, 25), (3, "definition", 14, 42), (4, "completion", 4, 14)):
    send({"jsonrpc": "2.0", "id": request_id, "method": "textDocument/" + method,
          "params": {"textDocument": document, "position": {"line": line, "character": character}}})
    receive()
send({"jsonrpc": "2.0", "id": 5, "method": "shutdown"})
receive()
send({"jsonrpc": "2.0", "method": "exit"})
print("(exit status %d)" % server.wait())
