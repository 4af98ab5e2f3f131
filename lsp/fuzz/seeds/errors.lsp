Content-Length: -1

Content-Length: 47

{"jsonrpc": "2.0", "id": "x", "method": "nope"}Content-Length: 5

{bad}Content-Length: 6

[1, 2]