#!/usr/bin/env python3
"""gcz80.py - function-level dead-code removal for sdcc Z80 programs (the
Z80 port's link step, ports/xbuild.sh; Z80_GC=0 turns it off).

    gcz80.py [--why NAME ...] OUTDIR MAIN.asm [MORE.asm ...] -- MEMBER.asm|.s ...

sdld links whole modules: a library module comes in with every function
and table in it once one of its symbols is needed, and the firmware's own
module (the library built into it) keeps everything it defines.  gcz80
reads the sdasz80 sources: what sdcc -c wrote next to each .rel (MAIN,
MORE: the program's modules, always linked) and the library's members
(linked as sdld links an archive member: when it defines a global symbol
that is still needed; the first member wins), follows the references
from _main, and writes to OUTDIR each source with only what is reachable.

A module is split at its column-0 labels (`_f::`, `_f:` for statics,
`_tab:`; sdcc's own `00105$:` locals stay inside): each label owns the
lines up to the next label or `.area`.  A block that may fall into the
next one (its last instruction is not an unconditional ret / jp / jr)
keeps that one too.  An initialised variable's data (`_x` in
_INITIALIZED) keeps its initialiser (`__xinit__x` in _INITIALIZER), and
the two are dropped together, so crt0's one block copy still pairs them;
a module whose two lists do not pair up is kept whole.  Lines outside
any block (the _GSINIT code for static locals) are kept, and what they
refer to is reachable.  Hand-written sources (not "File Created by SDCC")
are kept whole.  `.globl` lines of dropped names go too (sdasz80 would
otherwise make them undefined references).  Symbols nothing here defines
(crt0, z80.lib: __divsint, ___sdcc_call_iy, the linker's s__HEAP) are
left to sdld.

Prints the files written, one per line, in link order (the program's
first, then members in the order they were needed); "gcz80: ..." with
the kept share of the source goes to stderr.  Exit status 2 on a usage
error or an unreadable file.  --why NAME prints the chain of references
that keeps NAME (or "not kept").
"""
import os
import re
import sys

COL0_LABEL = re.compile(r"([A-Za-z_.][\w.$]*)(::?)(?!=)")
ANY_LABEL = re.compile(r"\s*([A-Za-z_.][\w.$]*)::?(?!=)")
EQUATE = re.compile(r"\s*([A-Za-z_.][\w.$]*)\s*(==?)\s*\S")
NAME = re.compile(r"(?<![\w.$])[A-Za-z_][\w$]*")
GLOBL = re.compile(r"\s*\.globl\s+(.*)")
NO_REFS = re.compile(r"\s*\.(globl|area|module|optsdcc)\b")
STOPS = re.compile(r"(ret|reti|retn|jp\s+[^,]+|jr\s+[^,]+)$")


def code(line):
    """A line without its comment and strings."""
    return re.sub(r'"[^"]*"', "", line).split(";", 1)[0].rstrip()


def names(line):
    return set() if NO_REFS.match(line) else set(NAME.findall(code(line)))


class Block:
    """A label and the lines it owns, in one area."""

    def __init__(self, name, area, first):
        self.name, self.area, self.lines = name, area, [first]
        self.refs = set()
        self.live = self.equate = False

    def falls_through(self):
        if self.equate:
            return False
        head = COL0_LABEL.sub("", self.lines[0], 1)
        body = [c for c in map(code, [head] + self.lines[1:]) if c.strip()]
        if not body:
            return True
        last = body[-1].strip()
        if last.startswith("."):
            return False                     # data
        return not STOPS.match(re.sub(r"\s+", " ", last))


class Module:
    def __init__(self, path):
        self.path = path
        with open(path) as f:
            self.lines = f.read().splitlines()
        self.sdcc = any("File Created by SDCC" in l for l in self.lines[:4])
        self.used = False
        self.blocks = {}
        self.seq = []         # loose lines (str) and Blocks, in order
        self.globl = set()
        for l in self.lines:
            m = GLOBL.match(code(l))
            if m:
                self.globl.update(n.strip() for n in m.group(1).split(","))
        if self.sdcc:
            self._split()
        if not self.sdcc or not self._pair_initialisers():
            self.blocks, self.seq = {}, list(self.lines)
        defs, self.exports = set(self.blocks), set()
        for l in self.lines:
            m = ANY_LABEL.match(l) or EQUATE.match(l)
            if m:
                defs.add(m.group(1))
                if re.match(r"\s*[\w.$]+\s*(::|==)", l) or m.group(1) in self.globl:
                    self.exports.add(m.group(1))
        self.defs = defs
        # what the module needs however little of it is kept
        self.roots = set()
        for p in self.seq:
            if isinstance(p, str):
                self.roots |= names(p)
        self.roots -= defs - set(self.blocks)

    def _split(self):
        area, cur = None, None
        for l in self.lines:
            m = COL0_LABEL.match(l)
            if m:
                cur = Block(m.group(1), area, l)
                cur.refs = names(l[m.end():])   # (code after the label)
                self.blocks[cur.name] = cur
                self.seq.append(cur)
                continue
            m = EQUATE.match(l)
            if m and not l[:1].isspace():
                b = Block(m.group(1), area, l)
                b.refs, b.equate = names(l.split("=")[-1]), True
                self.blocks[b.name] = b
                self.seq.append(b)
                cur = None
                continue
            a = re.match(r"\s*\.area\s+(\w+)", l)
            if a:
                area, cur = a.group(1), None
            if cur is None:
                self.seq.append(l)
            else:
                cur.lines.append(l)
        blocks = [p for p in self.seq if isinstance(p, Block)]
        for b in blocks:
            for l in b.lines[1:]:
                b.refs |= names(l)
            b.refs.discard(b.name)
        for a, b in zip(blocks, blocks[1:]):
            if a.area == b.area and a.area not in ("_INITIALIZED", "_INITIALIZER") and a.falls_through():
                a.refs.add(b.name)

    def _pair_initialisers(self):
        data = [b.name for b in self.blocks.values() if b.area == "_INITIALIZED"]
        init = [b.name for b in self.blocks.values() if b.area == "_INITIALIZER"]
        if ["__xinit_" + n for n in data] != init:
            sys.stderr.write("gcz80: %s: initialised data and initialisers do not pair; kept whole\n"
                             % self.path)
            return False
        for n in data:
            self.blocks[n].refs.add("__xinit_" + n)
        return True

    def text(self):
        if not self.blocks:
            return self.lines
        kept = {n for n, b in self.blocks.items() if b.live}
        needed = set(self.roots)
        for n in kept:
            needed |= self.blocks[n].refs
        out = []
        for p in self.seq:
            if isinstance(p, Block):
                if p.live:
                    out.extend(p.lines)
                continue
            m = GLOBL.match(code(p))
            if m:
                ns = [n.strip() for n in m.group(1).split(",")]
                if not any(n in kept or (n not in self.blocks and n in needed) for n in ns):
                    continue
            out.append(p)
        return out


def reach(progs, members, why=None):
    """Marks what _main reaches; returns the modules to link, in order.
    why: a dict that gets, for each block kept, the name that needed it."""
    order, owner, pending = [], {}, []
    archive = {}
    for m in members:
        for e in sorted(m.exports):
            archive.setdefault(e, m)

    def use(m):
        m.used = True
        order.append(m)
        for e in m.exports:
            owner.setdefault(e, m)
        pending.extend((m, r, m.path) for r in sorted(m.roots))

    for m in progs:
        use(m)
    pending.append((progs[0], "_main", "crt0"))
    while pending:
        m, n, by = pending.pop()
        if n in m.blocks:
            t = m
        elif n in m.defs:
            continue
        else:
            t = owner.get(n)
            if t is None:
                t = archive.get(n)
                if t is None or t.used:
                    continue            # crt0, z80.lib or the linker
                use(t)
        b = t.blocks.get(n)
        if b is None or b.live:
            continue
        b.live = True
        if why is not None:
            why[n] = by
        pending.extend((t, r, n) for r in sorted(b.refs))
    return order


def main(argv):
    why = {}
    trace = []
    while len(argv) > 2 and argv[1] == "--why":
        trace.append(argv[2])
        del argv[1:3]
    if len(argv) < 3 or "--" not in argv[2:] or argv[1] in ("-h", "--help"):
        sys.stderr.write(__doc__)
        return 2
    k = argv.index("--", 2)
    try:
        progs = [Module(p) for p in argv[2:k]]
        members = [Module(p) for p in argv[k + 1:]]
    except OSError as e:
        sys.stderr.write("gcz80: %s\n" % e)
        return 2
    if not progs:
        sys.stderr.write(__doc__)
        return 2
    os.makedirs(argv[1], exist_ok=True)
    total = kept = 0
    for m in reach(progs, members, why):
        path = os.path.join(argv[1], os.path.basename(m.path))
        with open(path, "w") as f:
            f.write("\n".join(m.text()) + "\n")
        for b in m.blocks.values():
            size = sum(len(l) for l in b.lines)
            total += size
            kept += size if b.live else 0
        print(path)
    for n in trace:
        chain = [n]
        while chain[-1] in why and len(chain) < 50:
            chain.append(why[chain[-1]])
        sys.stderr.write("gcz80: %s\n" % (" <- ".join(chain) if n in why else n + ": not kept"))
    sys.stderr.write("gcz80: kept %d of %d bytes of function and data source\n" % (kept, total))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
