#!/usr/bin/env python3
"""Whether two builds of a binary hold the same machine code, function by function.

A refactor that must not move a number or a nanosecond (a helper shared by three loops, an
attribute, a renamed argument) can be shown to have changed no instruction: build the bench
binary before and after (`cargo bench --bench batched --no-run` prints its path; builds are
deterministic), copy each aside, and run

    python3 benches/same_code.py OLD NEW

It disassembles both (`objdump -d`), masks what moves with any change to the source (the
addresses, jump and call targets, and the hashes in symbol names), and compares each function's
instructions. Functions of one name (the instances of a generic function) are compared as a
set: the linker may lay them out in another order. It prints the functions that differ and
exits 1 if any do. A function that differs only in register allocation is reported too: read
the diff (`--show`) before calling a change neutral.

The default (legacy) symbol names leave out a generic function's type parameters, so every
batched loop is one of the `pulp` dispatcher's instances, and a difference does not say whose.
Built with `RUSTFLAGS="-C symbol-mangling-version=v0"` (into a target directory of its own) and
compared with `--demangle`, each instance is named with its types: the model, the spectrum and
the lane operation. A type renamed by the change then shows as names found in one build only.
"""

import re
import subprocess
import sys
from collections import defaultdict
from difflib import unified_diff

HEADER = re.compile(r"^[0-9a-f]+ <(.*)>:$")
HASH = re.compile(r"17h[0-9a-f]{16}E|\.llvm\.[0-9]+|\[[0-9a-f]{1,16}\]")
ADDRESS = re.compile(r"^\s*[0-9a-f]+:")
# Greedy: a demangled v0 name holds `<` and `>` of its own.
TARGET = re.compile(r"<.*>")
# Addresses and large offsets in the operands: four or more hex digits.
HEX = re.compile(r"[0-9a-f]{4,}")
# An instruction's mnemonic (kept as it is, so that `fadd`, spelt in hex letters, stays) and
# its operands.
INSTRUCTION = re.compile(r"^(\s*\S*)(.*)$")


def functions(binary, demangle):
    """Each function's instructions, masked, by name (a sorted list per name)."""
    out = subprocess.run(
        ["objdump", "-d", "--no-show-raw-insn"] + (["-C"] if demangle else []) + [binary],
        capture_output=True, text=True, check=True,
    ).stdout
    found = defaultdict(list)
    name, body = None, []
    for line in out.splitlines():
        header = HEADER.match(line)
        if header:
            if name is not None:
                found[name].append("\n".join(body))
            name, body = HASH.sub("", header.group(1)), []
        elif name is not None and line.strip():
            mnemonic, operands = INSTRUCTION.match(ADDRESS.sub("", line)).groups()
            body.append(mnemonic + HEX.sub("X", TARGET.sub("<>", operands)))
    if name is not None:
        found[name].append("\n".join(body))
    return {k: sorted(v) for k, v in found.items()}


def main():
    flags = {"--show", "--demangle"}
    args = [a for a in sys.argv[1:] if a not in flags]
    if len(args) != 2:
        sys.exit("usage: same_code.py [--show] [--demangle] OLD NEW")
    old, new = (functions(b, "--demangle" in sys.argv) for b in args)
    differ = sorted(k for k in old.keys() | new.keys() if old.get(k) != new.get(k))
    only = (len(old.keys() - new.keys()), len(new.keys() - old.keys()))
    print(f"{len(old)} and {len(new)} function names ({only[0]} and {only[1]} in one build only);"
          f" {len(differ)} differ")
    for name in differ:
        print(f"  {name}")
        if "--show" in sys.argv:
            if name not in new or name not in old:
                print(f"    only in {'OLD' if name in old else 'NEW'}")
            for a, b in zip(old.get(name, []), new.get(name, [])):
                diff = unified_diff(a.splitlines(), b.splitlines(), lineterm="", n=1)
                print("\n".join(diff))
    sys.exit(1 if differ else 0)


if __name__ == "__main__":
    main()
