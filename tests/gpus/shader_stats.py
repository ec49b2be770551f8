#!/usr/bin/python3
"""The tables of make shader-stats (tests/gpus/shader_stats.sh): WORK holds programs.txt (key, stage),
uses.txt (key, scene@pipeline) and logs/GPU.log (compile_stats' output with the driver's statistics
lines among it). Writes OUT.md."""
import os
import re
import subprocess
import sys

# name in the logs, what the table calls it, which boards carry it
GPUS = [
    ("vc4", "VC4", "Raspberry Pi Zero, 1, 2, 3 (VideoCore IV)"),
    ("v3d", "V3D 4.2", "Raspberry Pi 4, 400, CM4"),
    ("lima", "Mali-400", "Allwinner H3/H5/A64, Rockchip RK3328, Amlogic S905 (lima)"),
    ("panfrost-t720", "Mali-T720", "Midgard boards (panfrost)"),
    ("panfrost-g52", "Mali-G52", "Bifrost boards: Rockchip RK3566/RK3568, Amlogic S922X (panfrost)"),
    ("freedreno-a306", "Adreno 306", "Snapdragon 410 boards (freedreno)"),
    ("freedreno-a530", "Adreno 530", "Snapdragon 820 boards (freedreno)"),
]
# The targets of the kiosk's shaders (docs/BENCH.md): no spills on V3D 4.2 or Bifrost, at least 4
# threads on V3D, compiled in at most 3 s of an x86 core by V3D's compiler.
TARGET_THREADS_V3D = 4
TARGET_COMPILE_S = 3.0

FRAGMENT = re.compile(r"\b(FS|FRAG|MESA_SHADER_FRAGMENT|FRAGMENT|fragment)\s+shader:\s*(\d+) inst")
THREADS = re.compile(r"(\d+) threads")
WAVES = re.compile(r"(\d+) waves")
SPILLS = re.compile(r"(\d+):(\d+) spills:fills")
RESULT = re.compile(r"^== result (\S+) (\S+) cpu_ms=(\d+) ?(.*)$")
FAILURES = ("Failed to register allocate", "failed to", "Failed to compile", "error:")


def writes_two_targets(path):
    """whether the fragment shader writes gl_FragData[1] once preprocessed (glslang's -E: the macros
    of common.glsl name it in every program, and only the MRT variants use it)"""
    try:
        out = subprocess.run(["glslangValidator", "-E", "-S", "frag", path], capture_output=True, text=True,
                             errors="replace").stdout
    except OSError:
        return False
    return "gl_FragData[1]" in out


def read_pairs(path):
    pairs = []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if len(parts) == 2:
                pairs.append((parts[0], parts[1]))
    return pairs


def parse_log(path):
    """key -> dict(status, why, cpu_s, inst, threads, spills, fills)"""
    out = {}
    if not os.path.exists(path):
        return out
    current = None
    with open(path, errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("== program "):
                key = os.path.basename(line.split()[2])
                current = out.setdefault(key, {"status": "no result", "why": "", "cpu_s": None,
                                               "inst": None, "threads": None, "spills": 0, "fills": 0,
                                               "failure": ""})
                continue
            if line.startswith("== ended "):
                key = os.path.basename(line.split()[2])
                entry = out.setdefault(key, {"inst": None, "threads": None, "spills": 0, "fills": 0,
                                             "cpu_s": None, "why": "", "failure": ""})
                entry["status"] = "crashed"
                entry["why"] = "compile_stats ended with " + " ".join(line.split()[3:]) + " (a crash or time-out)"
                continue
            if current is None:
                continue
            m = RESULT.match(line)
            if m:
                current["status"] = m.group(2)
                current["cpu_s"] = int(m.group(3)) / 1000.0
                current["why"] = m.group(4).strip()
                continue
            if line.startswith("== end "):
                current = None
                continue
            m = FRAGMENT.search(line)
            if m:
                inst = int(m.group(2))
                current["inst"] = max(current["inst"] or 0, inst)
                t = THREADS.search(line) or WAVES.search(line)
                if t:
                    threads = int(t.group(1))
                    current["threads"] = threads if current["threads"] is None else min(current["threads"], threads)
                s = SPILLS.search(line)
                if s:
                    current["spills"] = max(current["spills"], int(s.group(1)))
                    current["fills"] = max(current["fills"], int(s.group(2)))
                continue
            if any(word in line for word in FAILURES) and not current["failure"]:
                current["failure"] = line.strip()[:160]
    return out


def verdict(entry):
    """'ok' or the reason this program does not run on the GPU"""
    if entry is None:
        return "not run"
    if entry["status"] == "compile":
        return "does not compile: " + entry["why"]
    if entry["status"] == "link":
        return "does not link: " + entry["why"]
    if entry["status"] == "draw":
        return "not drawn: " + entry["why"]
    if entry["status"] != "ok":
        return entry.get("why") or entry["status"]
    if entry["failure"]:
        return entry["failure"]
    if entry["inst"] is None:
        return "no statistics (the driver compiled no fragment shader)"
    return "ok"


def cell(entry):
    v = verdict(entry)
    if v != "ok":
        short = v.replace("|", "/")
        return "**fails**: " + (short[:70] + "..." if len(short) > 70 else short)
    parts = ["%d inst" % entry["inst"]]
    if entry["threads"] is not None:
        parts.append("%d thr" % entry["threads"])
    if entry["spills"] or entry["fills"]:
        parts.append("**%d:%d spills**" % (entry["spills"], entry["fills"]))
    parts.append("%.1f s" % entry["cpu_s"])
    return ", ".join(parts)


def main():
    work, scope, out_md = sys.argv[1], sys.argv[2], sys.argv[3]
    programs = read_pairs(os.path.join(work, "programs.txt"))
    all_count = len(programs)
    uses = {}
    for key, label in read_pairs(os.path.join(work, "uses.txt")):
        uses.setdefault(key, [])
        if label not in uses[key]:
            uses[key].append(label)
    logs = {gpu: parse_log(os.path.join(work, "logs", gpu + ".log")) for gpu, _, _ in GPUS}
    renderers = {}
    caps = {}
    for gpu, _, _ in GPUS:
        for path in (os.path.join(work, "logs", gpu + ".caps"), os.path.join(work, "logs", gpu + ".log")):
            if not os.path.exists(path):
                continue
            with open(path, errors="replace") as f:
                for line in f:
                    if line.startswith("== renderer ") and gpu not in renderers:
                        renderers[gpu] = line[len("== renderer "):].strip()
                    if line.startswith("== caps ") and gpu not in caps:
                        caps[gpu] = dict(kv.split("=", 1) for kv in line.split()[2:] if "=" in kv)

    kiosk = [k for k, _ in programs if "kiosk@kiosk" in uses.get(k, [])]
    two_targets = set(k for k, _ in programs if writes_two_targets(os.path.join(work, "programs", k + ".frag")))
    one_buffer = set(g for g, _, _ in GPUS if caps.get(g, {}).get("draw_buffers") == "1")

    def applies(gpu, key):
        """whether bentray can build this program for this GPU: a two-target program never is where
        there is one draw buffer (bentray builds the one-target variants there)"""
        return not (gpu in one_buffer and key in two_targets)
    if scope == "kiosk":
        programs = [p for p in programs if p[0] in kiosk]
    lines = []
    w = lines.append
    w("<!-- written by make shader-stats (tests/gpus/shader_stats.sh); do not edit -->")
    w("## On the GPUs of an exhibit")
    w("")
    w("Every shader program bentray builds for the shipped scenes (each with `render.pipeline` = auto, "
      "multipass and fused, and multipass with one target a pass, `render.mrt = off`; the packed path's, "
      "`render.precision = packed` (\"packed\": the multipass scheme one target a pass on floats packed into RGBA8 "
      "texels, which a GPU without float textures takes); the "
      "variants a GPU takes, `BT_FAULT=gpu_rasterizer` (on exact orbits the single pass's walk in a pass of its own, "
      "`render.orbit_walk = separate`, and for comparison in the frame's own pass, \"single-inline\"; the "
      "integrated pass's chord cull read from its uniforms; one target a pass, the intersection stage's hit found "
      "and shaded in passes of their own, `render.hit_shading = separate`) and for the "
      "shipped kiosk configuration (every variant its compile-ahead builds), compiled by the real compilers of the exhibit's GPUs: Mesa %s's drivers over their noop "
      "drm-shim, which compile for the GPU and draw nothing. Each program is linked and drawn once, each sampler with a texture of the format bentray binds to it "
      "(the ray state and the orbit table in the best float format the GPU samples, the rest RGBA8: a driver "
      "compiles the variant for the textures bound), into RGBA8 targets. "
      "`inst`: the fragment shader's instructions (each compiler counts its own kind; loops count once); "
      "`thr`: threads (V3D, VC4, Mali) or waves (Adreno) it runs with; spills:fills where the "
      "register allocator spilled; then the CPU seconds the link and first draw took on one core of "
      "this machine. The counts say whether a shader fits a GPU, not how fast it runs there: that "
      "rests on the loops' turns, which the compilers cannot see (the Pi 4 estimates in the kiosk "
      "section above rest on this machine's measured times and the GFLOPS ratio)." % mesa_version(work))
    w("")
    if scope == "kiosk":
        w("This run (`tests/gpus/shader_stats.sh --kiosk`) compiled the kiosk's %d programs only, of the %d "
          "distinct programs bentray builds for the shipped scenes and the kiosk." % (len(kiosk), all_count))
    else:
        w("%d distinct programs, %d of them in the kiosk." % (len(programs), len(kiosk)))
    w("")
    w("Drivers as they reported themselves:")
    w("")
    for gpu, name, boards in GPUS:
        w("- %s (%s): %s" % (name, boards, renderers.get(gpu, "no context (see build/shader-stats/logs/%s.log)" % gpu)))
    w("")
    w("### What each driver offers")
    w("")
    w("As the driver reports it in a GLES context (compile_stats' `== caps` line): what bentray's render "
      "paths need (docs/HARDWARE.md says which path each board takes). ES 3 samples float textures in core; "
      "32-bit float render targets take EXT_color_buffer_float there, and ES 2 names no extension for "
      "them (\"untested\": only a draw and a read-back tell, which bentray's own probe does on the "
      "board and a noop shim cannot). `highp bits`: the fragment stage's highp float precision as "
      "reported (Mali-400 reports 23 and computes in 16-bit floats).")
    w("")
    w("| GPU | GLES | float textures | half-float textures | float targets | half-float targets | draw buffers | highp bits |")
    w("|---|---|---|---|---|---|---|---|")
    for gpu, name, _ in GPUS:
        c = caps.get(gpu)
        if not c:
            w("| %s | no caps line | | | | | | |" % name)
            continue
        w("| %s | %s | %s | %s | %s | %s | %s | %s |" % (
            name, c.get("gles", "?"), c.get("float_textures", "?"), c.get("half_float_textures", "?"),
            c.get("float_targets", "?"), c.get("half_float_targets", "?"), c.get("draw_buffers", "?"),
            c.get("highp_bits", "?")))
    w("")
    w("### Summary")
    w("")
    w("Programs that write two targets (MRT) are counted only where the driver has more than one draw "
      "buffer: elsewhere bentray builds the one-target variants (`render.mrt = off`, in the table as "
      "\"multipass-1target\"), and the two-target ones show as \"n/a\".")
    w("")
    w("| GPU | programs that compile | fail | spill | fewest threads | most instructions | slowest compile, s |")
    w("|---|---|---|---|---|---|---|")
    for gpu, name, _ in GPUS:
        log = logs[gpu]
        entries = [log.get(k) for k, _ in programs if applies(gpu, k)]
        ok = [e for e in entries if verdict(e) == "ok"]
        spill = [e for e in ok if e["spills"] or e["fills"]]
        threads = [e["threads"] for e in ok if e["threads"] is not None]
        w("| %s | %d of %d | %d | %d | %s | %s | %s |" % (
            name, len(ok), len(entries), len(entries) - len(ok), len(spill),
            min(threads) if threads else "-", max(e["inst"] for e in ok) if ok else "-",
            "%.1f" % max(e["cpu_s"] for e in ok) if ok else "-"))
    w("")
    w("### The kiosk's targets")
    w("")
    v3d = logs["v3d"]
    g52 = logs["panfrost-g52"]
    checks = [
        ("no spills on V3D 4.2", [k for k in kiosk if verdict(v3d.get(k)) != "ok" or v3d[k]["spills"] or v3d[k]["fills"]]),
        ("no spills on Bifrost (Mali-G52)", [k for k in kiosk if verdict(g52.get(k)) != "ok" or g52[k]["spills"] or g52[k]["fills"]]),
        ("at least %d threads on V3D" % TARGET_THREADS_V3D,
         [k for k in kiosk if verdict(v3d.get(k)) != "ok" or (v3d[k]["threads"] or 0) < TARGET_THREADS_V3D]),
        ("compiled by V3D's compiler in at most %.0f s" % TARGET_COMPILE_S,
         [k for k in kiosk if verdict(v3d.get(k)) != "ok" or v3d[k]["cpu_s"] > TARGET_COMPILE_S]),
    ]
    stage_of = dict(programs)
    for what, missed in checks:
        if missed:
            w("- %s: **missed** by %d of %d kiosk programs (%s)" % (
                what, len(missed), len(kiosk), ", ".join(sorted(set(stage_of[k] for k in missed)))))
        else:
            w("- %s: met by all %d kiosk programs" % (what, len(kiosk)))
    w("")
    w("### Every program")
    w("")
    w("Named by its stage (the fragment shader's own file) and the scenes and pipelines that build it.")
    w("")
    w("| program | built by | " + " | ".join(name for _, name, _ in GPUS) + " |")
    w("|---|---|" + "---|" * len(GPUS))
    for key, stage in sorted(programs, key=lambda p: (p[1], uses.get(p[0], [""])[0])):
        who = uses.get(key, [])
        shown = ", ".join(("kiosk" if u == "kiosk@kiosk" else u.replace("@", " ")) for u in who[:4]) + (" and %d more" % (len(who) - 4) if len(who) > 4 else "")
        w("| %s `%s` | %s | " % (stage, key, shown) + " | ".join(
            cell(logs[g].get(key)) if applies(g, key) else "n/a (two targets, one draw buffer)" for g, _, _ in GPUS) + " |")
    w("")
    os.makedirs(os.path.dirname(os.path.abspath(out_md)), exist_ok=True)
    tmp = out_md + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines))
    os.replace(tmp, out_md)


def mesa_version(work):
    src = os.path.join(os.path.dirname(work), "mesa-shim", "src")
    try:
        for name in sorted(os.listdir(src)):
            if name.startswith("mesa-") and os.path.isdir(os.path.join(src, name)):
                return name[5:]
    except OSError:
        pass
    return "(unknown)"


if __name__ == "__main__":
    main()
