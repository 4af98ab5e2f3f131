Content-Length: 57

{"jsonrpc": "2.0", "method": "initialized", "params": {}}Content-Length: 1564

{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "file:///s/area_light.sgl.frag", "languageId": "glsl", "version": 1, "text": "#version 330 core\n// One sample of a rectangular area light: the light is sampled by area, so\n// its pdf is converted to the projected solid angle at the shading point with\n// the r^2 / cos Jacobian before it divides the estimate.\n#include <safegi/prelude.sgl>\n\nspace world;\n\nuniform point<world>       lightCorner;\nuniform vector<world>      lightEdgeU;\nuniform vector<world>      lightEdgeV;\nuniform normal<world>      lightNormal;\nuniform spectrum<radiance> Le;\nuniform float<area>        lightArea;\nuniform spectrum<brdf>     Kd;\n\nin point<world>  P;\nin normal<world> N;\nin vec2          xi;                       // uniform random numbers\n\nout vec4 fragColor;\n\nvoid main() {\n    point<world> Y = lightCorner + lightEdgeU * xi.x + lightEdgeV * xi.y;\n    vector<world> toLight = Y - P;\n    float<area> r2 = dot(toLight, toLight);\n    direction<world> wi = normalize(toLight);\n    float<proj> cosX = max(dot(normalize(N), wi), 0.0);\n    float<proj> cosY = max(-dot(normalize(lightNormal), wi), 0.0);\n    float<pdf_area> pdfA = 1.0 / lightArea;\n    // Area measure at Y -> projected solid angle at P: the r^2 / cos Jacobian,\n    // where the cosine at the light turns area into solid angle.\n    float<pdf_projected_solid_angle> pdfW = pdfA * r2 / (cosX * float<solid_angle>(cosY));\n    spectrum<radiance> L = Kd * Le / pdfW;\n    fragColor = vec4(L, 1.0);\n}\n"}}}Content-Length: 172

{"jsonrpc": "2.0", "id": 2, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///s/area_light.sgl.frag"}, "position": {"line": 10, "character": 10}}}Content-Length: 177

{"jsonrpc": "2.0", "id": 3, "method": "textDocument/completion", "params": {"textDocument": {"uri": "file:///s/area_light.sgl.frag"}, "position": {"line": 10, "character": 20}}}Content-Length: 188

{"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": {"uri": "file:///s/area_light.sgl.frag", "version": 2}, "contentChanges": [{"text": "void main() {}\n"}]}}Content-Length: 50

{"jsonrpc": "2.0", "id": 99, "method": "shutdown"}Content-Length: 36

{"jsonrpc": "2.0", "method": "exit"}