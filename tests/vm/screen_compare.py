"""The virtual exhibit's screen against the headless renderer (tests/vm/drive.py).

The same kiosk configuration is run on the host with the headless screen: its devices replaced
by a script that only asks for a frame once the picture is refined, its buttons left out, the
knobs where the guest's start. That frame is what the guest's KMS screen must show, centred on the
screen (the kiosk letterboxes a frame smaller than the mode). The HUD is laid out for the screen it
is drawn on (its text scales with the screen's height), so the band it may cover, the top 30% of
the screen, is left out; everything below it is compared pixel for pixel.
"""
import os
import re
import struct
import subprocess
import zlib

# the top of the screen where the HUD's panel may be, as a share of the screen's height
HUD_BAND = 0.30
# a pixel differs when a channel is off by more than this many levels of 255
LEVELS = 16
# the headless screen's clock runs a thirtieth of a second a turn: the refined frame and its
# anti-aliasing are done well before this many seconds (33 bands and 4 x 33 more, one a turn), as
# the guest's screen is once still
FRAME_AT_SECONDS = 10.0


def reference_config(src, dst, events, out_dir, assets, speed_start):
    """kiosk.conf as the guest has it, for the headless screen: paths into the tree made absolute
    (assets), every [input] that turns a knob replaced by the script `events`, the other inputs
    and the buttons left out, the speed knob starting at speed_start."""
    with open(src, encoding="utf-8") as f:
        text = f.read().replace("../assets", assets)
    knob_inputs = set()
    for m in re.finditer(r"^\[(speed|mass)\]\n((?:(?!\[).*\n)*)", text, re.M):
        k = re.search(r"^input = (\S+)", m.group(2), re.M)
        if k:
            knob_inputs.add(k.group(1))
    lines, section = [], None
    for line in text.split("\n"):
        m = re.match(r"^\[(\S+)(?: (\S+))?\]", line)
        if m:
            section = (m.group(1), m.group(2))
            keep = section[0] != "button" and (section[0] != "input" or section[1] in knob_inputs)
            if keep:
                lines.append(line)
            if section[0] == "input" and keep:
                lines += ["type = script", "path = %s" % events]
            if section[0] == "display":
                lines += ["backend = headless", "headless_out = %s" % out_dir, "headless_frames = 1"]
            continue
        if section and section[0] in ("button", "input"):
            continue
        if section and section[0] == "display" and re.match(r"^[a-z_]+ =", line):
            continue
        if section and section[0] == "speed" and re.match(r"^start = ", line):
            line = "start = %s" % speed_start
        lines.append(line)
    with open(dst, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def render_reference(out, top, speed_start):
    """The refined first frame of the kiosk on the host's headless screen: (path, message)."""
    ref = os.path.join(out, "reference")
    os.makedirs(ref, exist_ok=True)
    events = os.path.join(ref, "refined.events")
    with open(events, "w", encoding="utf-8") as f:
        f.write("# the refined first picture, nothing turned\n%.1f frame\n" % FRAME_AT_SECONDS)
    conf = os.path.join(ref, "kiosk.conf")
    reference_config(os.path.join(top, "kiosk", "kiosk.conf"), conf, events, ref, os.path.join(top, "assets"),
                     speed_start)
    run = subprocess.run([os.path.join(top, "bentray"), "kiosk", "--config", conf, "--force"],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600)
    frame = os.path.join(ref, "frame_0001.png")
    return (frame if run.returncode == 0 and os.path.exists(frame) else None,
            "bentray kiosk --config %s: exit %d; %s" % (conf, run.returncode, " ".join(run.stdout.split("\n")[-3:])))


def read_png(path):
    """(width, height, RGB bytes) of an 8-bit RGB or RGBA PNG, as the kiosk writes them."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s: not a PNG" % path)
    pos, idat, width, height, bpp = 8, b"", 0, 0, 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6) or body[12] != 0:
                raise ValueError("%s: not an 8-bit RGB or RGBA PNG without interlacing" % path)
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = width * bpp
    rgb, prev = bytearray(), bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        prev = line
        rgb += line if bpp == 3 else bytes(v for j, v in enumerate(line) if j % 4 != 3)
    return width, height, bytes(rgb)


def compare(screen, frame):
    """The frame centred on the screen, below the HUD's band: a dict with the share of pixels that
    differ by more than LEVELS, the share that are equal, how many were compared and where; None
    when the frame does not fit the screen unscaled."""
    sw, sh, s = screen
    fw, fh, f = frame
    if fw > sw or fh > sh:
        return None
    ox, oy = (sw - fw) // 2, (sh - fh) // 2
    first = max(0, int(HUD_BAND * sh) - oy)
    differ = equal = count = 0
    for y in range(first, fh):
        row_s = s[((y + oy) * sw + ox) * 3:((y + oy) * sw + ox + fw) * 3]
        row_f = f[y * fw * 3:(y + 1) * fw * 3]
        if row_s == row_f:
            equal += fw
            count += fw
            continue
        for i in range(0, fw * 3, 3):
            d = max(abs(row_s[i] - row_f[i]), abs(row_s[i + 1] - row_f[i + 1]), abs(row_s[i + 2] - row_f[i + 2]))
            differ += d > LEVELS
            equal += d == 0
            count += 1
    return {"differ": differ / max(count, 1), "equal": equal / max(count, 1), "pixels": count,
            "offset": (ox, oy), "rows": (first + oy, fh + oy)}
