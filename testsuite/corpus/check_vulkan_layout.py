#!/usr/bin/env python3
"""Checks a safeglslc symbol table against the SPIR-V module of the same shader.

    check_vulkan_layout.py TABLE.json MODULE.spv

Every block member's offset, array stride and matrix stride, every
resource's descriptor set and binding, and every specialization constant's id
in the table must be what glslang decorated the module with (docs/symbol-table.md).
Prints one line per disagreement and exits 1 if there is any; exits 0 silently
when all agree. Used by run_vulkan_corpus.sh.
"""
import json
import struct
import sys

OP_NAME, OP_MEMBER_NAME, OP_TYPE_STRUCT, OP_TYPE_POINTER, OP_VARIABLE = 5, 6, 30, 32, 59
OP_DECORATE, OP_MEMBER_DECORATE = 71, 72
SPEC_ID, ARRAY_STRIDE, MATRIX_STRIDE, BINDING, DESCRIPTOR_SET, OFFSET = 1, 6, 7, 33, 34, 35


def literal_string(words):
    data = struct.pack(f"<{len(words)}I", *words)
    return data.split(b"\0", 1)[0].decode("utf-8", "replace")


class Module:
    def __init__(self, path):
        data = open(path, "rb").read()
        words = struct.unpack(f"<{len(data) // 4}I", data[: len(data) // 4 * 4])
        self.names, self.member_names, self.members = {}, {}, {}
        self.decorations, self.member_decorations = {}, {}
        self.pointee, self.variables = {}, []
        at = 5
        while at < len(words):
            count, opcode = words[at] >> 16, words[at] & 0xFFFF
            ops = words[at + 1 : at + count]
            if count == 0:
                break
            if opcode == OP_NAME:
                self.names[ops[0]] = literal_string(ops[1:])
            elif opcode == OP_MEMBER_NAME:
                self.member_names[(ops[0], ops[1])] = literal_string(ops[2:])
            elif opcode == OP_TYPE_STRUCT:
                self.members[ops[0]] = list(ops[1:])
            elif opcode == OP_TYPE_POINTER:
                self.pointee[ops[0]] = ops[2]
            elif opcode == OP_VARIABLE:
                self.variables.append((ops[1], ops[0]))  # (id, pointer type)
            elif opcode == OP_DECORATE:
                self.decorations[(ops[0], ops[1])] = ops[2] if len(ops) > 2 else 1
            elif opcode == OP_MEMBER_DECORATE:
                self.member_decorations[(ops[0], ops[1], ops[2])] = ops[3] if len(ops) > 3 else 1
            at += count

    def ids_named(self, name):
        return [i for i, n in self.names.items() if n == name]

    def variable_of_struct(self, struct_id):
        for var, pointer in self.variables:
            if self.pointee.get(pointer) == struct_id:
                return var
        return None


def check(table_path, module_path):
    table = json.load(open(table_path))
    module = Module(module_path)
    problems = []

    def expect(what, ours, theirs):
        if ours != theirs:
            problems.append(f"{what}: table {ours}, module {theirs}")

    for stage in table["stages"]:
        for symbol in stage["symbols"]:
            if symbol["kind"] == "block":
                structs = [i for i in module.ids_named(symbol["name"]) if i in module.members]
                if not structs:
                    continue  # a block the shader never uses is left out of the module
                struct_id = structs[0]
                variable = module.variable_of_struct(struct_id)
                for key, decoration in (("set", DESCRIPTOR_SET), ("binding", BINDING)):
                    if key in symbol and variable is not None:
                        expect(f"{symbol['name']} {key}", symbol[key], module.decorations.get((variable, decoration)))
                for index, type_id in enumerate(module.members[struct_id]):
                    name = module.member_names.get((struct_id, index))
                    member = next((m for m in symbol["members"] if m["name"] == name), None)
                    if member is None or "offset" not in member:
                        continue
                    where = f"{symbol['name']}.{name}"
                    expect(f"{where} offset", member["offset"], module.member_decorations.get((struct_id, index, OFFSET)))
                    if "matrix_stride" in member:
                        expect(f"{where} matrix_stride", member["matrix_stride"],
                               module.member_decorations.get((struct_id, index, MATRIX_STRIDE)))
                    if "array_stride" in member:
                        expect(f"{where} array_stride", member["array_stride"],
                               module.decorations.get((type_id, ARRAY_STRIDE)))
            elif symbol["storage"] == "uniform":
                variables = [i for i in module.ids_named(symbol["name"]) if any(v == i for v, _ in module.variables)]
                for key, decoration in (("set", DESCRIPTOR_SET), ("binding", BINDING)):
                    if key in symbol and variables:
                        expect(f"{symbol['name']} {key}", symbol[key], module.decorations.get((variables[0], decoration)))
        spec_ids = {v for (i, d), v in module.decorations.items() if d == SPEC_ID}
        for constant in stage.get("specialization_constants", []):
            named = [i for i in module.ids_named(constant["name"]) if (i, SPEC_ID) in module.decorations]
            if named:
                expect(f"{constant['name']} id", constant["id"], module.decorations[(named[0], SPEC_ID)])
            elif constant["id"] not in spec_ids:
                problems.append(f"{constant['name']}: id {constant['id']} is no SpecId of the module")
    return problems


if __name__ == "__main__":
    found = check(sys.argv[1], sys.argv[2])
    for line in found:
        print(line)
    sys.exit(1 if found else 0)
