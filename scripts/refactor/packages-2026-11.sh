#!/usr/bin/env bash
# Issue 32, item 4: packages by concept, so that no package cycle is left anywhere (root
# packages included). Moves classes between packages and rewrites what names them.
#
# Usage: scripts/refactor/packages-2026-11.sh   (from anywhere inside the work tree)
#
# Idempotent: a class already moved is left where it is, and the rewrites find nothing left to
# change, so the script can be run again on a tree that merged other branches since (their new
# files get the same import and package rewrites). Run the ArchUnit rules afterwards:
#   mvn -B -o -q -pl parpe-cli,parpe-gui -am test \
#     -Dtest='ArchitectureTest,ModuleLayersTest,GuiPackagesTest' -Dsurefire.failIfNoSpecifiedTests=false
#
# What it does, per move OLD.Class -> NEW: `git mv` of the class (in whichever module holds it)
# and of its tests named Class*Test / Class*Properties in the same package; the package line of
# the moved files; every fully qualified name OLD.Class in Java sources, docs and service files;
# an import of NEW.Class in every file of OLD that named Class without one, and an import in the
# moved file of each class of OLD it named without one; imports of a file's own package dropped.
# New packages get a package-info.java (kept if one is there).
set -euo pipefail
cd "$(git rev-parse --show-toplevel)"

MOVES=$(cat <<'EOF'
# parpe-sim: the root package is the top (Simulator, SimTarget); geometry is the bottom, and
# the snapshots the simulator publishes (built in internal, read by the IDE) sit just above it.
org.parpe.sim.Vec3                        org.parpe.sim.geom
org.parpe.sim.Mat3                        org.parpe.sim.geom
org.parpe.sim.Geo                         org.parpe.sim.geom
org.parpe.sim.BodyShape                   org.parpe.sim.geom
org.parpe.sim.PartKind                    org.parpe.sim.geom
org.parpe.sim.SimSnapshot                 org.parpe.sim.snapshot
org.parpe.sim.SimBody                     org.parpe.sim.snapshot
org.parpe.sim.SimContact                  org.parpe.sim.snapshot
# parpe-cli: the root package is the top (Main and its own commands); what every command
# shares moves below the command packages.
org.parpe.cli.UsageException              org.parpe.cli.options
org.parpe.cli.Inputs                      org.parpe.cli.options
org.parpe.cli.ClockOptions                org.parpe.cli.options
org.parpe.cli.ParamValues                 org.parpe.cli.options
org.parpe.cli.OutputFile                  org.parpe.cli.options
org.parpe.cli.TerminalLine                org.parpe.cli.terminal
org.parpe.cli.Progress                    org.parpe.cli.terminal
org.parpe.cli.FoldedDiagnostics           org.parpe.cli.terminal
org.parpe.cli.LoadReport                  org.parpe.cli.terminal
org.parpe.cli.WriterStream                org.parpe.cli.terminal
org.parpe.cli.InterruptHook               org.parpe.cli.terminal
org.parpe.cli.Canvas                      org.parpe.cli.plot
org.parpe.cli.PngCharts                   org.parpe.cli.plot
# parpe-serial: by protocol and family, not by when each was written.
org.parpe.serial.protocol.Command         org.parpe.serial.g1
org.parpe.serial.protocol.FrameDecoder    org.parpe.serial.g1
org.parpe.serial.protocol.FrameEncoder    org.parpe.serial.g1
org.parpe.serial.protocol.FrameHandler    org.parpe.serial.g1
org.parpe.serial.protocol.Protocol        org.parpe.serial.g1
org.parpe.serial.protocol.Crc16           org.parpe.serial.bus
org.parpe.serial.bus.BusMaster            org.parpe.serial.g1
org.parpe.serial.bus.Reply                org.parpe.serial.g1
org.parpe.serial.servo.host.G1Bus         org.parpe.serial.g1
org.parpe.serial.emu.BusEmulator          org.parpe.serial.g1.emu
org.parpe.serial.emu.ServoModule          org.parpe.serial.g1.emu
org.parpe.serial.servo.wire.Dxl2Codec     org.parpe.serial.dynamixel
org.parpe.serial.servo.wire.FeetechCodec  org.parpe.serial.feetech
EOF
)

# Tests of the G1 codec that are not named after one class.
EXTRA_TESTS=$(cat <<'EOF'
parpe-serial/src/test/java/org/parpe/serial/protocol/DecoderFuzzProperties.java org.parpe.serial.g1
parpe-serial/src/test/java/org/parpe/serial/protocol/FrameCodecTest.java        org.parpe.serial.g1
EOF
)

# Issue 32 item 6: one of each pair of classes with the same simple name gets the name of what
# it is (class, its new name; same package).
RENAMES=$(cat <<'EOF'
org.parpe.sim.Progress                    MotionTracker
org.parpe.core.load.Assembly              Includes
org.parpe.core.run.Evaluator              ExpressionEvaluator
org.parpe.core.run.Inputs                 TickInputs
org.parpe.gui.hardware.DialogHardware     ConnectedRobot
EOF
)

MOVES=$(grep -v '^#' <<<"$MOVES" | grep -v '^ *$')
export MOVES EXTRA_TESTS RENAMES

python3 - <<'PY'
import os, re, subprocess

moves = [l.split() for l in os.environ["MOVES"].splitlines()]
extra = [l.split() for l in os.environ["EXTRA_TESTS"].splitlines() if l.strip()]
MODULES = ["parpe-core", "parpe-sim", "parpe-serial", "parpe-cli", "parpe-gui"]
ROOTS = [f"{m}/src/{s}/java" for m in MODULES for s in ("main", "test")]

def pkg_dir(root, pkg):
    return os.path.join(root, *pkg.split("."))

def git_mv(src, dst):
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    subprocess.run(["git", "mv", src, dst], check=True)

def set_package(path, pkg):
    s = open(path, encoding="utf-8").read()
    t = re.sub(r"^package [\w.]+;", f"package {pkg};", s, count=1, flags=re.M)
    if t != s:
        open(path, "w", encoding="utf-8").write(t)

def moves_with(name, base):
    return base == name or re.fullmatch(name + r"(Test|Properties)", base) is not None

# 1. git mv, and the package line of what moved.
for fqn, new in moves:
    old, name = fqn.rsplit(".", 1)
    for root in ROOTS:
        for f in sorted(os.listdir(pkg_dir(root, old))) if os.path.isdir(pkg_dir(root, old)) else []:
            base = f[:-5] if f.endswith(".java") else None
            if base is None or not moves_with(name, base):
                continue
            if "/src/test/" in root and base == name:
                continue
            src = os.path.join(pkg_dir(root, old), f)
            dst = os.path.join(pkg_dir(root, new), f)
            git_mv(src, dst)
            set_package(dst, new)
def old_package(src):
    return ".".join(["org"] + src.split("/org/")[1].split("/")[:-1])
def extra_destination(src, new):
    return os.path.join(os.path.dirname(src).split("/org/")[0], *new.split("."), os.path.basename(src))
for src, new in extra:
    dst = extra_destination(src, new)
    if os.path.exists(src):
        git_mv(src, dst)
        set_package(dst, new)

# 2. Fully qualified names, in every Java source, doc and service file of the tree.
files = subprocess.run(["git", "ls-files"], capture_output=True, text=True, check=True).stdout.split()
texts = [f for f in files if os.path.isfile(f) and (f.endswith((".java", ".md")) or "/META-INF/services/" in f)]
for f in texts:
    s = open(f, encoding="utf-8").read()
    t = s
    for fqn, new in moves:  # the class and its tests
        name = fqn.rsplit(".", 1)[1]
        t = re.sub(re.escape(fqn) + r"((?:Test|Properties)?)\b", new + "." + name + r"\1", t)
    for src, new in extra:
        base = os.path.basename(src)[:-5]
        t = re.sub(re.escape(old_package(src) + "." + base) + r"\b", new + "." + base, t)
    if t != s:
        open(f, "w", encoding="utf-8").write(t)

# 3. Imports that a package move makes necessary (same-package names need none before).
def package_of(path):
    m = re.search(r"^package ([\w.]+);", open(path, encoding="utf-8").read(), re.M)
    return m.group(1) if m else None

def java_files_of(pkg):
    out = []
    for root in ROOTS:
        d = pkg_dir(root, pkg)
        if os.path.isdir(d):
            out += [os.path.join(d, f) for f in sorted(os.listdir(d)) if f.endswith(".java")]
    return out

def add_import(path, fqn):
    s = open(path, encoding="utf-8").read()
    name = fqn.rsplit(".", 1)[1]
    if re.search(r"^import [\w.]+\." + name + ";", s, re.M):
        return  # imported already (from here, or another class of that name)
    lines = s.split("\n")
    imports = [i for i, l in enumerate(lines) if l.startswith("import ") and not l.startswith("import static ")]
    line = f"import {fqn};"
    if imports:
        at = next((i for i in imports if lines[i] > line), imports[-1] + 1)
    else:
        pk = next(i for i, l in enumerate(lines) if l.startswith("package "))
        at = pk + 1
        lines.insert(at, "")
        at += 1
    lines.insert(at, line)
    open(path, "w", encoding="utf-8").write("\n".join(lines))

COMMENTS = re.compile(r'/\*.*?\*/|//[^\n]*|"(?:\\.|[^"\\\n])*"', re.S)
def names(path, name):
    """Whether the code of path (not its comments or strings) names the class."""
    code = COMMENTS.sub("", open(path, encoding="utf-8").read())
    code = re.sub(r"^(package|import) .*$", "", code, flags=re.M)
    return re.search(r"(?<![\w.])" + name + r"\b", code) is not None

def refer(path, fqn):
    """An import where the code names the class; where only javadoc links it, a qualified link
    (an import for a comment would be a dependency the code does not have)."""
    name = fqn.rsplit(".", 1)[1]
    if names(path, name):
        add_import(path, fqn)
        return
    s = open(path, encoding="utf-8").read()
    t = re.sub(r"(\{@link(?:plain)?\s+)" + name + r"\b", r"\g<1>" + fqn, s)
    if t != s:
        open(path, "w", encoding="utf-8").write(t)

for fqn, new in moves:
    old, name = fqn.rsplit(".", 1)
    # Files left in the old package that name the moved class.
    for f in java_files_of(old):
        if os.path.basename(f) != "package-info.java":
            refer(f, new + "." + name)
    # The moved class (and its tests, and the extra tests from its old package), naming
    # classes of its old package.
    extras = [extra_destination(src, n) for src, n in extra if n == new and old_package(src) == old]
    for f in java_files_of(new):
        base = os.path.basename(f)[:-5]
        if not (moves_with(name, base) or f in extras):
            continue
        for g in java_files_of(old):
            other = os.path.basename(g)[:-5]
            if other != "package-info" and ("/src/test/" in g) <= ("/src/test/" in f):
                refer(f, old + "." + other)
        for fqn2, new2 in moves:
            old2, name2 = fqn2.rsplit(".", 1)
            if old2 == old and new2 != new:
                refer(f, new2 + "." + name2)

# 4. Renames within a package: the file (and ClassTest), the fully qualified name everywhere,
# and the simple name in the files of its package and in those that import it (unless they
# import another class of that name).
renames = [l.split() for l in os.environ["RENAMES"].splitlines() if l.strip()]
for fqn, new_name in renames:
    pkg, old_name = fqn.rsplit(".", 1)
    for root in ROOTS:
        for suffix in ("", "Test"):
            src = os.path.join(pkg_dir(root, pkg), old_name + suffix + ".java")
            if os.path.exists(src):
                git_mv(src, os.path.join(pkg_dir(root, pkg), new_name + suffix + ".java"))
    targets = set(java_files_of(pkg))
    for f in texts:
        if os.path.exists(f) and re.search(re.escape(fqn) + r"\b", open(f, encoding="utf-8").read()):
            targets.add(f)
    for f in sorted(targets):
        s = open(f, encoding="utf-8").read()
        t = re.sub(re.escape(fqn) + r"(Test)?\b", pkg + "." + new_name + r"\1", s)
        other = re.search(r"^import (?!" + re.escape(pkg) + r"\.)[\w.]+\." + old_name + ";", t, re.M)
        if f.endswith(".java") and not other:
            t = re.sub(r"(?<![\w.])" + old_name + r"(Test)?\b", new_name + r"\1", t)
        if t != s:
            open(f, "w", encoding="utf-8").write(t)

# 5. No import of a file's own package.
for root in ROOTS:
    for d, _, fs in os.walk(root):
        for f in fs:
            if not f.endswith(".java"):
                continue
            p = os.path.join(d, f)
            s = open(p, encoding="utf-8").read()
            pkg = package_of(p)
            t = re.sub(r"^import " + re.escape(pkg) + r"\.[A-Z]\w*;\n", "", s, flags=re.M) if pkg else s
            if t != s:
                open(p, "w", encoding="utf-8").write(t)
PY

# 6. A package-info for each new package; the old G1 package's goes with its classes.
info() { # module package text
    local f="$1/src/main/java/${2//.//}/package-info.java"
    if [ ! -e "$f" ]; then
        mkdir -p "$(dirname "$f")"
        printf '/**\n%s\n */\npackage %s;\n' "$3" "$2" >"$f"
        git add "$f"
    fi
}
old_info=parpe-serial/src/main/java/org/parpe/serial/protocol/package-info.java
if [ -e "$old_info" ]; then git rm -q "$old_info"; fi

info parpe-sim org.parpe.sim.geom \
' * The simulator'"'"'s geometry (public API): vectors {@link org.parpe.sim.geom.Vec3}, rotations
 * {@link org.parpe.sim.geom.Mat3}, the vector maths of {@link org.parpe.sim.geom.Geo}, and what a
 * body is: its {@link org.parpe.sim.geom.BodyShape} and {@link org.parpe.sim.geom.PartKind}. The
 * bottom of parpe-sim: it uses no other package of it.'
info parpe-sim org.parpe.sim.snapshot \
' * What the simulator publishes for the IDE and the grader to read (public API): the immutable
 * {@link org.parpe.sim.snapshot.SimSnapshot} of one tick, its bodies
 * ({@link org.parpe.sim.snapshot.SimBody}) and contacts ({@link org.parpe.sim.snapshot.SimContact}).
 * Built by the simulator'"'"'s internals, which is why it sits below them; no SWT or AWT types.'
info parpe-cli org.parpe.cli.options \
' * What the commands read from their options, checked before any work starts: input files
 * ({@link org.parpe.cli.options.Inputs}), output files ({@link org.parpe.cli.options.OutputFile}),
 * {@code --tick}/{@code --duration} and {@code --param}, and the
 * {@link org.parpe.cli.options.UsageException} a bad value ends with (exit code 2).'
info parpe-cli org.parpe.cli.terminal \
' * What the commands write on the terminal and how they end: the load report, folded run
 * diagnostics, the progress line rewritten in place, Ctrl-C and SIGTERM, and the exit codes
 * more than one command returns.'
info parpe-cli org.parpe.cli.plot \
' * The PNG pictures of the command line: the plots of {@code --plot}, the sweep, optimisation
 * and merge ({@link org.parpe.cli.plot.PngCharts}, drawn with XChart) and the canvas diagrams
 * are drawn on ({@link org.parpe.cli.plot.Canvas}).'
info parpe-serial org.parpe.serial.g1 \
' * The G1 module bus (docs/hardware-protocol.md), PARPE'"'"'s reconstruction of the PolyBot G1
 * protocol: frame layout, command codes, an allocation-free encoder and a streaming decoder that
 * resynchronises on garbage, the request/reply transactions with timeouts and retries
 * ({@link org.parpe.serial.g1.BusMaster}), and {@link org.parpe.serial.g1.G1Bus}, which puts it
 * behind the {@link org.parpe.serial.servo.ServoBus} every protocol has (public API).'
info parpe-serial org.parpe.serial.g1.emu \
' * An emulator of G1-style modules that serves the G1 bus on a serial device: servo motion with a
 * speed limit, limp and hold, a watchdog, sensor readings, over the shared
 * {@link org.parpe.serial.emu.ServedLine} and its injected faults (public API).'
info parpe-serial org.parpe.serial.dynamixel \
' * The Dynamixel family: Protocol 2.0 packets ({@link org.parpe.serial.dynamixel.Dxl2Codec}:
 * header {@code FF FF FD 00}, CRC-16 with polynomial 0x8005, byte stuffing; ROBOTIS e-Manual,
 * Protocol 2.0) behind the {@link org.parpe.serial.servo.wire.PacketCodec} the control-table
 * host and emulator are written against (public API).'
info parpe-serial org.parpe.serial.feetech \
' * The Feetech family, STS and SCS: packets ({@link org.parpe.serial.feetech.FeetechCodec}:
 * header {@code FF FF}, one'"'"'s-complement checksum) behind the
 * {@link org.parpe.serial.servo.wire.PacketCodec} the control-table host and emulator are written
 * against (public API).'
echo "packages-2026-11: done"
