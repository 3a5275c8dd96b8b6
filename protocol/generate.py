#!/usr/bin/env python3
"""Generate the usv-link artefacts from protocol/messages.toml (the one source of truth).

Writes:
  protocol/c/usv_messages.h                 C99 structs, pack/unpack, constants (firmware)
  protocol/c/tests/usv_fields.h             field access by index, for the C vector tool
  backend/usvstation/link/messages.py       Python message types, enums, constants
  protocol/README.md                        the message tables between the GENERATED markers
  protocol/vectors/frames.json              shared frame vectors (encoded by the Python codec)
  protocol/vectors/streams.json             garbage + frames streams with the frames to recover

`python protocol/generate.py` rewrites them; `--check` exits 1 naming every stale file.
The tests run `--check` (tests/unit/test_protocol_generated.py).
"""

from __future__ import annotations

import argparse
import json
import random
import sys
import textwrap
import tomllib
import zlib
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
DEFINITION = ROOT / "protocol" / "messages.toml"
C_HEADER = ROOT / "protocol" / "c" / "usv_messages.h"
C_FIELDS = ROOT / "protocol" / "c" / "tests" / "usv_fields.h"
PY_MODULE = ROOT / "backend" / "usvstation" / "link" / "messages.py"
README = ROOT / "protocol" / "README.md"
FRAMES = ROOT / "protocol" / "vectors" / "frames.json"
STREAMS = ROOT / "protocol" / "vectors" / "streams.json"
BEGIN_MARK = "<!-- BEGIN GENERATED: message tables (protocol/generate.py) -->"
END_MARK = "<!-- END GENERATED -->"

TYPES = {  # name: (size, struct code, C type, min, max)
    "u8": (1, "B", "uint8_t", 0, 0xFF),
    "u16": (2, "H", "uint16_t", 0, 0xFFFF),
    "u32": (4, "I", "uint32_t", 0, 0xFFFFFFFF),
    "i8": (1, "b", "int8_t", -0x80, 0x7F),
    "i16": (2, "h", "int16_t", -0x8000, 0x7FFF),
    "i32": (4, "i", "int32_t", -0x80000000, 0x7FFFFFFF),
}
HEADER_LEN = 3  # version, msg_id, seq
CRC_LEN = 2
COBS_MAX_BLOCK = 254


def load_definition(path: Path = DEFINITION) -> dict[str, Any]:
    """Load and validate the definition; raise ValueError naming the problem."""
    with path.open("rb") as fh:
        d = tomllib.load(fh)
    ids, names = set(), set()
    for msg in d["messages"]:
        if msg["id"] in ids or msg["name"] in names:
            raise ValueError(f"duplicate message id or name: {msg['name']} ({msg['id']})")
        ids.add(msg["id"])
        names.add(msg["name"])
        if not 0 <= msg["id"] <= 255:
            raise ValueError(f"{msg['name']}: id {msg['id']} is not a byte")
        for i, f in enumerate(msg["fields"]):
            if f["type"] == "text":
                if i != len(msg["fields"]) - 1:
                    raise ValueError(f"{msg['name']}.{f['name']}: text must be the last field")
            elif f["type"] not in TYPES:
                raise ValueError(f"{msg['name']}.{f['name']}: unknown type {f['type']!r}")
            if "enum" in f and f["enum"] not in d["enums"]:
                raise ValueError(f"{msg['name']}.{f['name']}: unknown enum {f['enum']!r}")
        body = HEADER_LEN + payload_max(msg) + CRC_LEN
        if body >= COBS_MAX_BLOCK:
            raise ValueError(f"{msg['name']}: frame of {body} bytes needs a COBS 0xFF block")
    clash = set(d["enums"]) & {camel(msg["name"]) for msg in d["messages"]}
    if clash:
        raise ValueError(f"enum names clash with message type names: {sorted(clash)}")
    hb = d["messages"][0]
    frozen = [(f["name"], f["type"]) for f in hb["fields"][:2]]
    if hb["id"] != 0 or frozen != [("definition_crc", "u32"), ("protocol_version", "u8")]:
        raise ValueError("HEARTBEAT must be id 0 and start with definition_crc u32, "
                         "protocol_version u8 (frozen across versions)")
    return d


def payload_min(msg: dict[str, Any]) -> int:
    return sum(TYPES[f["type"]][0] for f in msg["fields"] if f["type"] != "text")


def payload_max(msg: dict[str, Any]) -> int:
    return payload_min(msg) + sum(f["max"] for f in msg["fields"] if f["type"] == "text")


def canonical_text(d: dict[str, Any]) -> str:
    """What the definition CRC covers: names, ids, types, enum values, constants (not docs)."""
    lines = [f"{d['protocol']} {d['version']}"]
    lines += [f"const {k}={v}" for k, v in d["constants"].items()]
    for name, values in d["enums"].items():
        lines.append(f"enum {name}:" + ",".join(f"{k}={v}" for k, v in values.items()))
    for msg in d["messages"]:
        fields = ",".join(
            f"{f['name']}:{f['type']}" + (f"[{f['max']}]" if f["type"] == "text" else "")
            + (f"/{f['enum']}" if "enum" in f else "")
            for f in msg["fields"]
        )
        lines.append(f"msg {msg['id']} {msg['name']}:{fields}")
    return "\n".join(lines) + "\n"


def definition_crc(d: dict[str, Any]) -> int:
    return zlib.crc32(canonical_text(d).encode("utf-8"))


def camel(name: str) -> str:
    return "".join(part.capitalize() for part in name.split("_"))


def struct_format(msg: dict[str, Any]) -> str:
    return "<" + "".join(TYPES[f["type"]][1] for f in msg["fields"] if f["type"] != "text")


def _doc(f: dict[str, Any]) -> str:
    parts = [f.get("unit", ""), f.get("doc", "")]
    if "enum" in f:
        parts.append(f"enum {f['enum']}")
    return "; ".join(p for p in parts if p)


# ----------------------------------------------------------------------------- Python


def gen_python(d: dict[str, Any]) -> str:
    out = [
        '"""usv-link message types. GENERATED by protocol/generate.py from protocol/messages.toml:',
        'do not edit; edit the definition and run `python protocol/generate.py`."""',
        "",
        "from __future__ import annotations",
        "",
        "from enum import IntEnum, IntFlag",
        "from typing import NamedTuple",
        "",
        f'PROTOCOL = "{d["protocol"]}"',
        f"PROTOCOL_VERSION = {d['version']}",
        f"DEFINITION_CRC = 0x{definition_crc(d):08X}",
    ]
    out += [f"{k} = {v}" for k, v in d["constants"].items()]
    out.append(f"MAX_PAYLOAD = {max(payload_max(m) for m in d['messages'])}")
    for name, values in d["enums"].items():
        base = "IntFlag" if name == "Flag" else "IntEnum"
        out += ["", "", f"class {name}({base}):"]
        out += [f"    {k} = {v}" for k, v in values.items()]
    for msg in d["messages"]:
        out += ["", "", f"class {camel(msg['name'])}(NamedTuple):"]
        head = f'"""{msg["name"]} (id {msg["id"]}, from {msg["direction"]}): {msg["doc"]}'
        out += textwrap.wrap(head, 96, initial_indent="    ", subsequent_indent="    ")
        out.append("")
        for f in msg["fields"]:
            line = f"{f['name']}: {f['type']}; {_doc(f)}".rstrip("; ")
            out += textwrap.wrap(line, 96, initial_indent="    ", subsequent_indent="        ")
        out.append('    """')
        out.append("")
        for f in msg["fields"]:
            out.append(f"    {f['name']}: {'str' if f['type'] == 'text' else 'int'}")
        out.append("")
        out.append(f"    ID = {msg['id']}")
        out.append(f'    NAME = "{msg["name"]}"')
        out.append(f'    FORMAT = "{struct_format(msg)}"')
        text = [f for f in msg["fields"] if f["type"] == "text"]
        out.append(f"    TEXT_MAX = {text[0]['max'] if text else 0}")
    out += ["", "", "MESSAGE_TYPES = ("]
    out += [f"    {camel(m['name'])}," for m in d["messages"]]
    out += [")", ""]
    return "\n".join(out)


# ----------------------------------------------------------------------------- C


def _c_name(msg: dict[str, Any]) -> str:
    return msg["name"].lower()


def gen_c_header(d: dict[str, Any]) -> str:
    crc = definition_crc(d)
    o = [
        "/* usv-link message definitions for the boat firmware (C99, no malloc).",
        " * GENERATED by protocol/generate.py from protocol/messages.toml: do not edit.",
        " * Multi-byte fields are little-endian on the wire; pack/unpack never depend on",
        " * the host's byte order or struct layout. */",
        "#ifndef USV_MESSAGES_H",
        "#define USV_MESSAGES_H",
        "",
        "#include <stddef.h>",
        "#include <stdint.h>",
        "#include <string.h>",
        "",
        f"#define USV_PROTOCOL_VERSION {d['version']}u",
        f"#define USV_DEFINITION_CRC 0x{crc:08X}UL",
    ]
    o += [f"#define USV_{k} {v}u" for k, v in d["constants"].items()]
    max_pl = max(payload_max(m) for m in d["messages"])
    o += [
        f"#define USV_MAX_PAYLOAD {max_pl}u",
        f"#define USV_HEADER_LEN {HEADER_LEN}u",
        f"#define USV_CRC_LEN {CRC_LEN}u",
        "/* a frame body is header + payload + CRC; COBS adds one byte (bodies are < 254) */",
        "#define USV_MAX_BODY (USV_HEADER_LEN + USV_MAX_PAYLOAD + USV_CRC_LEN)",
        "#define USV_MAX_ENCODED (USV_MAX_BODY + 1u)",
        "/* on the wire: 0x00, COBS(body), 0x00 */",
        "#define USV_MAX_WIRE (USV_MAX_ENCODED + 2u)",
        "",
    ]
    for name, values in d["enums"].items():
        prefix = "USV_" + "".join("_" + c if c.isupper() and i else c
                                  for i, c in enumerate(name)).upper()
        o.append(f"enum usv_{prefix[4:].lower()} {{")
        items = list(values.items())
        for i, (k, v) in enumerate(items):
            o.append(f"    {prefix}_{k} = {v}{',' if i < len(items) - 1 else ''}")
        o += ["};", ""]
    for m in d["messages"]:
        cn = _c_name(m)
        o.append(f"#define USV_MSG_{m['name']} {m['id']}u")
        o.append(f"#define USV_{m['name']}_MIN_LEN {payload_min(m)}u")
        o.append(f"#define USV_{m['name']}_MAX_LEN {payload_max(m)}u")
    o.append("")
    o += [
        "static inline void usv_put_u8(uint8_t *p, uint8_t v) { p[0] = v; }",
        "static inline void usv_put_u16(uint8_t *p, uint16_t v)",
        "{ p[0] = (uint8_t)(v & 0xFFu); p[1] = (uint8_t)(v >> 8); }",
        "static inline void usv_put_u32(uint8_t *p, uint32_t v)",
        "{ usv_put_u16(p, (uint16_t)(v & 0xFFFFu)); usv_put_u16(p + 2, (uint16_t)(v >> 16)); }",
        "static inline void usv_put_i8(uint8_t *p, int8_t v) { p[0] = (uint8_t)v; }",
        "static inline void usv_put_i16(uint8_t *p, int16_t v) { usv_put_u16(p, (uint16_t)v); }",
        "static inline void usv_put_i32(uint8_t *p, int32_t v) { usv_put_u32(p, (uint32_t)v); }",
        "static inline uint8_t usv_get_u8(const uint8_t *p) { return p[0]; }",
        "static inline uint16_t usv_get_u16(const uint8_t *p)",
        "{ return (uint16_t)((uint16_t)p[0] | ((uint16_t)p[1] << 8)); }",
        "static inline uint32_t usv_get_u32(const uint8_t *p)",
        "{ return (uint32_t)usv_get_u16(p) | ((uint32_t)usv_get_u16(p + 2) << 16); }",
        "/* two's complement decoding without implementation-defined conversions */",
        "static inline int8_t usv_get_i8(const uint8_t *p)",
        "{ return p[0] < 0x80u ? (int8_t)p[0] : (int8_t)(-(int)(0xFFu - p[0]) - 1); }",
        "static inline int16_t usv_get_i16(const uint8_t *p)",
        "{ uint16_t u = usv_get_u16(p);",
        "  return u < 0x8000u ? (int16_t)u : (int16_t)(-(int32_t)(0xFFFFu - u) - 1); }",
        "static inline int32_t usv_get_i32(const uint8_t *p)",
        "{ uint32_t u = usv_get_u32(p);",
        "  return u < 0x80000000UL ? (int32_t)u : -(int32_t)(0xFFFFFFFFUL - u) - 1; }",
        "",
    ]
    for m in d["messages"]:
        cn = _c_name(m)
        o.append(f"/* {m['name']} (id {m['id']}, from {m['direction']}): {m['doc']} */")
        o.append("typedef struct {")
        for f in m["fields"]:
            if f["type"] == "text":
                o.append(f"    uint8_t {f['name']}_len; /* bytes used in {f['name']} */")
                o.append(f"    char {f['name']}[{f['max']}]; /* {_doc(f)} */")
            else:
                c = f"    {TYPES[f['type']][2]} {f['name']};"
                o.append(c + (f" /* {_doc(f)} */" if _doc(f) else ""))
        o.append(f"}} usv_{cn}_t;")
        o.append("")
        # pack
        o.append("/* Write the payload; returns its length. p needs "
                 f"USV_{m['name']}_MAX_LEN bytes. */")
        o.append(f"static inline size_t usv_{cn}_pack(const usv_{cn}_t *m, uint8_t *p)")
        o.append("{")
        off = 0
        for f in m["fields"]:
            if f["type"] == "text":
                o.append(f"    size_t n = m->{f['name']}_len > {f['max']}u ? {f['max']}u : "
                         f"m->{f['name']}_len;")
                o.append(f"    memcpy(p + {off}, m->{f['name']}, n);")
                o.append(f"    return {off}u + n;")
            else:
                o.append(f"    usv_put_{f['type']}(p + {off}, m->{f['name']});")
                off += TYPES[f["type"]][0]
        if not any(f["type"] == "text" for f in m["fields"]):
            o.append(f"    return {off}u;")
        o.append("}")
        # unpack
        o.append("/* Read a payload of len bytes; returns 1, or 0 if len is wrong for it. */")
        o.append(f"static inline int usv_{cn}_unpack(const uint8_t *p, size_t len, usv_{cn}_t *m)")
        o.append("{")
        o.append(f"    if (len < USV_{m['name']}_MIN_LEN || len > USV_{m['name']}_MAX_LEN) "
                 "return 0;")
        off = 0
        for f in m["fields"]:
            if f["type"] == "text":
                o.append(f"    m->{f['name']}_len = (uint8_t)(len - {off}u);")
                o.append(f"    memcpy(m->{f['name']}, p + {off}, len - {off}u);")
            else:
                o.append(f"    m->{f['name']} = usv_get_{f['type']}(p + {off});")
                off += TYPES[f["type"]][0]
        o.append("    return 1;")
        o.append("}")
        o.append("")
    o.append("typedef union {")
    for m in d["messages"]:
        o.append(f"    usv_{_c_name(m)}_t {_c_name(m)};")
    o += ["} usv_message_t;", ""]
    o.append("/* Is msg_id a message of this protocol version? */")
    o.append("static inline int usv_msg_known(uint8_t msg_id)")
    o.append("{")
    o.append("    switch (msg_id) {")
    for m in d["messages"]:
        o.append(f"    case USV_MSG_{m['name']}:")
    o += ["        return 1;", "    default: return 0;", "    }", "}", ""]
    o.append("/* Is len a valid payload length for msg_id? (0 for unknown ids) */")
    o.append("static inline int usv_payload_len_ok(uint8_t msg_id, size_t len)")
    o.append("{")
    o.append("    switch (msg_id) {")
    for m in d["messages"]:
        o.append(f"    case USV_MSG_{m['name']}: return len >= USV_{m['name']}_MIN_LEN && "
                 f"len <= USV_{m['name']}_MAX_LEN;")
    o += ["    default: return 0;", "    }", "}", ""]
    o.append("/* Unpack any message by id; returns 1 on success. */")
    o.append("static inline int usv_unpack(uint8_t msg_id, const uint8_t *p, size_t len, "
             "usv_message_t *m)")
    o.append("{")
    o.append("    switch (msg_id) {")
    for m in d["messages"]:
        o.append(f"    case USV_MSG_{m['name']}: return usv_{_c_name(m)}_unpack(p, len, "
                 f"&m->{_c_name(m)});")
    o += ["    default: return 0;", "    }", "}", ""]
    o.append("/* Pack any message by id into p (USV_MAX_PAYLOAD bytes); returns the length, "
             "0 for an unknown id. */")
    o.append("static inline size_t usv_pack(uint8_t msg_id, const usv_message_t *m, uint8_t *p)")
    o.append("{")
    o.append("    switch (msg_id) {")
    for m in d["messages"]:
        o.append(f"    case USV_MSG_{m['name']}: "
                 f"return usv_{_c_name(m)}_pack(&m->{_c_name(m)}, p);")
    o += ["    default: return 0;", "    }", "}", "", "#endif /* USV_MESSAGES_H */", ""]
    return "\n".join(o)


def gen_c_fields(d: dict[str, Any]) -> str:
    """Test helper: set and print fields by index (used by the C vector tool only)."""
    o = [
        "/* Field access by index for the C vector tool. GENERATED by protocol/generate.py. */",
        "#ifndef USV_FIELDS_H",
        "#define USV_FIELDS_H",
        "",
        "#include <stdio.h>",
        '#include "../usv_messages.h"',
        "",
        "/* Set numeric field `index` of message msg_id to v; returns 0 for a bad index. */",
        "static int usv_test_set(uint8_t msg_id, usv_message_t *m, size_t index, long long v)",
        "{",
        "    switch (msg_id) {",
    ]
    for m in d["messages"]:
        o.append(f"    case USV_MSG_{m['name']}:")
        o.append("        switch (index) {")
        for i, f in enumerate(m["fields"]):
            if f["type"] != "text":
                o.append(f"        case {i}: m->{_c_name(m)}.{f['name']} = "
                         f"({TYPES[f['type']][2]})v; return 1;")
        o += ["        default: return 0;", "        }"]
    o += ["    default: return 0;", "    }", "}", ""]
    o += [
        "/* Set the text field of msg_id (if any) from n bytes; returns 0 if it has none. */",
        "static int usv_test_set_text(uint8_t msg_id, usv_message_t *m, const char *s, size_t n)",
        "{",
        "    switch (msg_id) {",
    ]
    for m in d["messages"]:
        for f in m["fields"]:
            if f["type"] == "text":
                o.append(f"    case USV_MSG_{m['name']}:")
                o.append(f"        if (n > {f['max']}u) n = {f['max']}u;")
                o.append(f"        memcpy(m->{_c_name(m)}.{f['name']}, s, n);")
                o.append(f"        m->{_c_name(m)}.{f['name']}_len = (uint8_t)n;")
                o.append("        return 1;")
    o += ["    default: return 0;", "    }", "}", ""]
    o += [
        "/* Print the fields as space-separated decimals, text as hex (or '-' if empty). */",
        "static void usv_test_print(FILE *out, uint8_t msg_id, const usv_message_t *m)",
        "{",
        "    size_t i;",
        "    (void)i;",
        "    switch (msg_id) {",
    ]
    for m in d["messages"]:
        o.append(f"    case USV_MSG_{m['name']}:")
        for f in m["fields"]:
            ref = f"m->{_c_name(m)}.{f['name']}"
            if f["type"] == "text":
                o.append(f"        if ({ref}_len == 0) fputs(\" -\", out); else fputc(' ', out);")
                o.append(f"        for (i = 0; i < {ref}_len; i++) "
                         f"fprintf(out, \"%02x\", (unsigned)(unsigned char){ref}[i]);")
            elif f["type"].startswith("i"):
                o.append(f"        fprintf(out, \" %ld\", (long){ref});")
            else:
                o.append(f"        fprintf(out, \" %lu\", (unsigned long){ref});")
        o.append("        break;")
    o += ["    default: break;", "    }", "}", "", "#endif /* USV_FIELDS_H */", ""]
    return "\n".join(o)


# ----------------------------------------------------------------------------- README


def gen_tables(d: dict[str, Any]) -> str:
    o = [
        BEGIN_MARK,
        "",
        f"Protocol `{d['protocol']}` version {d['version']}, definition CRC-32 "
        f"`0x{definition_crc(d):08X}`.",
        "",
        "### Constants",
        "",
        "| name | value |",
        "|---|---|",
    ]
    o += [f"| `{k}` | {v} |" for k, v in d["constants"].items()]
    o += ["", "### Enumerations", ""]
    for name, values in d["enums"].items():
        o.append(f"- **{name}**: " + ", ".join(f"{k} = {v}" for k, v in values.items()))
    o.append("")
    o += ["### Messages", "", "| id | name | from | payload bytes |", "|---|---|---|---|"]
    for m in d["messages"]:
        lo, hi = payload_min(m), payload_max(m)
        size = str(lo) if lo == hi else f"{lo}..{hi}"
        o.append(f"| {m['id']} | [{m['name']}](#{m['name'].lower()}) | {m['direction']} | {size} |")
    for m in d["messages"]:
        o += ["", f"#### {m['name']}", "", f"id {m['id']}, sent by {m['direction']}. {m['doc']}",
              "", "| offset | field | type | unit | meaning |", "|---|---|---|---|---|"]
        off = 0
        for f in m["fields"]:
            typ = f"text[0..{f['max']}]" if f["type"] == "text" else f["type"]
            meaning = f.get("doc", "") + (f" (enum {f['enum']})" if "enum" in f else "")
            o.append(f"| {off} | `{f['name']}` | {typ} | {f.get('unit', '')} | {meaning.strip()} |")
            if f["type"] != "text":
                off += TYPES[f["type"]][0]
    o += ["", END_MARK]
    return "\n".join(o)


def render_readme(d: dict[str, Any], current: str) -> str:
    start, end = current.find(BEGIN_MARK), current.find(END_MARK)
    if start < 0 or end < 0:
        raise ValueError(f"{README} lacks the generated-section markers")
    return current[:start] + gen_tables(d) + current[end + len(END_MARK):]


# ----------------------------------------------------------------------------- vectors


def sample_values(msg: dict[str, Any], kind: str, rng: random.Random) -> dict[str, Any]:
    """Field values for a vector: 'min', 'max', 'zero' or 'random'."""
    values: dict[str, Any] = {}
    for f in msg["fields"]:
        if f["type"] == "text":
            values[f["name"]] = {
                "min": "", "zero": "failsafe: no heartbeat for 3.0 s, holding",
                "max": "x" * f["max"], "random": "mission 7 activated: 32 items, crc ok ✓",
            }[kind]
            continue
        _, _, _, lo, hi = TYPES[f["type"]]
        values[f["name"]] = {"min": lo, "max": hi, "zero": 0, "random": rng.randint(lo, hi)}[kind]
    return values


def gen_vectors(d: dict[str, Any]) -> tuple[str, str]:
    sys.path.insert(0, str(ROOT / "backend"))
    from usvstation.link import codec, messages

    rng = random.Random(20240604)
    enc = codec.Encoder()
    frames = []
    for m in d["messages"]:
        cls = getattr(messages, camel(m["name"]))
        for kind in ("zero", "min", "max", "random", "random"):
            values = sample_values(m, kind, rng)
            frame = enc.encode(cls(**values))
            frames.append({"name": m["name"], "id": m["id"], "seq": frame_seq(frame),
                           "fields": values, "frame_hex": frame.hex()})
    streams = []
    all_frames = [bytes.fromhex(v["frame_hex"]) for v in frames]
    for _ in range(64):
        parts, expected = [], []
        for _ in range(rng.randint(0, 6)):
            parts.append(bytes(rng.randrange(256) for _ in range(rng.randint(0, 40))))
            f = rng.choice(all_frames)
            parts.append(f)
            expected.append(f.hex())
        parts.append(bytes(rng.randrange(256) for _ in range(rng.randint(0, 40))))
        streams.append({"stream_hex": b"".join(parts).hex(), "embedded_frames_hex": expected})
    head = {"protocol": d["protocol"], "version": d["version"],
            "definition_crc": f"0x{definition_crc(d):08X}"}
    frames_doc = {**head, "doc": "Each frame as sent on the wire (0x00, COBS(body), 0x00) "
                  "for the given field values and sequence number.", "frames": frames}
    streams_doc = {**head, "doc": "Random garbage with valid frames embedded: a parser must "
                   "recover every embedded frame, in order (it may also report extra frames "
                   "only if garbage happens to pass the CRC).", "streams": streams}
    return (json.dumps(frames_doc, indent=1, ensure_ascii=False) + "\n",
            json.dumps(streams_doc, indent=1) + "\n")


def frame_seq(frame: bytes) -> int:
    from usvstation.link import codec

    return codec.decode_body(frame)[2]


# ----------------------------------------------------------------------------- main


def outputs(d: dict[str, Any]) -> dict[Path, str]:
    """Every generated file and its content. The Python module is written first by main()
    because the vectors are encoded with it."""
    res = {
        PY_MODULE: gen_python(d),
        C_HEADER: gen_c_header(d),
        C_FIELDS: gen_c_fields(d),
        README: render_readme(d, README.read_text(encoding="utf-8")),
    }
    return res


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="only report stale files, exit 1 if any")
    args = ap.parse_args(argv)
    d = load_definition()
    files = outputs(d)
    if not args.check:
        for path, text in files.items():
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
    frames_text, streams_text = gen_vectors(d)
    files[FRAMES], files[STREAMS] = frames_text, streams_text
    stale = [p for p, t in files.items()
             if not p.exists() or p.read_text(encoding="utf-8") != t]
    if args.check:
        for p in stale:
            print(f"stale: {p.relative_to(ROOT)} (run python protocol/generate.py)")
        return 1 if stale else 0
    for p in stale:
        p.write_text(files[p], encoding="utf-8")
    print(f"definition CRC 0x{definition_crc(d):08X}; wrote {len(files)} files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
