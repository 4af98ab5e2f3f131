!Content-Length: 57

{"jsonrpc": "2.0", "method": "initialized", "params": {}}Content-Length: 804

{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "file:///s/transform.sgl.vert", "languageId": "glsl", "version": 1, "text": "#version 330 core\n// Object-space geometry to world space for shading and to clip space for the\n// rasteriser. Normals use the inverse transpose (a non-rigid map).\n#include <safegi/prelude.sgl>\n\nspace object;\nspace world;\nspace clip;\n\nuniform map<object, world>   worldFromObject;\nuniform projmap<world, clip> clipFromWorld;\n\nlayout(location = 0) in point<object>  position;\nlayout(location = 1) in normal<object> objectNormal;\n\nout point<world>  P;\nout normal<world> N;\n\nvoid main() {\n    P = worldFromObject * position;\n    N = normalize(worldFromObject * objectNormal);\n    gl_Position = clipFromWorld * P;\n}\n"}}}Content-Length: 176

{"jsonrpc": "2.0", "id": 2, "method": "textDocument/definition", "params": {"textDocument": {"uri": "file:///s/transform.sgl.vert"}, "position": {"line": 12, "character": 10}}}Content-Length: 171

{"jsonrpc": "2.0", "id": 3, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///s/transform.sgl.vert"}, "position": {"line": 12, "character": 12}}}Content-Length: 272

{"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": {"uri": "file:///s/transform.sgl.vert", "version": 2}, "contentChanges": [{"text": "// é → 😀\n", "range": {"start": {"line": 3, "character": 0}, "end": {"line": 3, "character": 0}}}]}}Content-Length: 50

{"jsonrpc": "2.0", "id": 99, "method": "shutdown"}Content-Length: 36

{"jsonrpc": "2.0", "method": "exit"}