#!/usr/bin/env python3
"""Check a generated walker replay page (app/replay_template.html filled with data)
in headless Chromium.

Usage: check_replay.py PATH_TO_HTML [--chromium /usr/bin/chromium] [--keep DIR]

One Chromium run loads the page from a file:// URL, lets 2 s of virtual time pass,
and gives (a) the page's console messages on stderr (--enable-logging=stderr --v=0),
(b) a 1000x600 screenshot and (c) the DOM after the scripts ran (--dump-dom).

Chromium (tested with 156 on Debian 12) prints every console message at INFO level,
whatever its level, as
    [pid:tid:date/time:INFO:CONSOLE:LINE] "MESSAGE", source: URL (LINE)
(older versions: "INFO:CONSOLE(LINE)]"); uncaught exceptions appear the same way
with a message starting "Uncaught". Since the level cannot be told apart, and the
viewer logs nothing in normal use, ANY console message from the page is a failure.

Exit codes: 0 page looks fine (one summary line), 1 check failed (reasons printed),
2 Chromium not found (the caller decides whether that is a skip).
"""
import argparse
import collections
import html
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

WINDOW = (1000, 600)
VIRTUAL_TIME_MS = 2000
TIMEOUT_S = 90
MIN_CHANGED = 0.01        # >= 1 % of pixels must differ from the most common colour
CANVAS_BAND = (0.10, 0.85)  # rows (fractions of the height) that the canvas fills
MIN_BAND_COLOURS = 3      # the canvas band must hold at least this many colours ...
MIN_BAND_CHANGED = 0.005  # ... and >= 0.5 % of its pixels differ from its main colour

# Lines of Chromium's log that carry page console output or uncaught errors.
CONSOLE_RE = re.compile(r'CONSOLE[:(]\d*\)?\]\s*(?P<msg>.*)')
OTHER_RE = re.compile(r'console-message|Uncaught', re.IGNORECASE)


def find_chromium(requested):
    """Path of the Chromium binary, or None."""
    if requested:
        if os.path.isfile(requested) and os.access(requested, os.X_OK):
            return requested
        return shutil.which(requested)
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def run_chromium(chromium, page, tmp):
    """Runs headless Chromium once; returns (returncode, stdout DOM, stderr, png path)."""
    shot = os.path.join(tmp, "shot.png")
    cmd = [
        chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
        "--no-first-run", "--disable-background-networking", "--disable-component-update",
        "--disable-sync", "--user-data-dir=" + os.path.join(tmp, "profile"),
        "--enable-logging=stderr", "--v=0",
        "--window-size=%d,%d" % WINDOW, "--hide-scrollbars",
        "--virtual-time-budget=%d" % VIRTUAL_TIME_MS,
        "--screenshot=" + shot, "--dump-dom",
        "file://" + os.path.abspath(page),
    ]
    proc = subprocess.run(cmd, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                          errors="replace", timeout=TIMEOUT_S)
    return proc.returncode, proc.stdout, proc.stderr, shot


def console_messages(stderr):
    """Page console messages and uncaught errors found in Chromium's stderr."""
    found = []
    for line in stderr.splitlines():
        m = CONSOLE_RE.search(line)
        if m:
            found.append(m.group("msg").strip())
        elif OTHER_RE.search(line):
            found.append(line.strip())
    return found


def read_png_stdlib(path):
    """Decodes an 8-bit, non-interlaced RGB/RGBA/grey PNG; returns (w, h, rgb bytes)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG file")
    pos, idat, ihdr = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        pos += 12 + length
    w, h, depth, ctype, _, _, interlace = ihdr
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(ctype)
    if depth != 8 or interlace or channels is None:
        raise ValueError("unsupported PNG (depth %d, colour type %d, interlace %d)" % (depth, ctype, interlace))
    raw, stride, bpp = zlib.decompress(b"".join(idat)), w * channels, channels
    out, prev = bytearray(), bytearray(stride)
    for y in range(h):
        ftype, row = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        if ftype == 1:
            for i in range(bpp, stride):
                row[i] = (row[i] + row[i - bpp]) & 255
        elif ftype == 2:
            row = bytearray((a + b) & 255 for a, b in zip(row, prev))
        elif ftype == 3:
            for i in range(stride):
                row[i] = (row[i] + ((row[i - bpp] if i >= bpp else 0) + prev[i]) // 2) & 255
        elif ftype == 4:
            for i in range(stride):
                a = row[i - bpp] if i >= bpp else 0
                b, c = prev[i], (prev[i - bpp] if i >= bpp else 0)
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += row
        prev = row
    if channels == 3:
        return w, h, bytes(out)
    rgb = bytearray()
    for i in range(0, len(out), channels):
        rgb += bytes(out[i:i + 3]) if channels == 4 else bytes([out[i]] * 3)
    return w, h, bytes(rgb)


def read_png(path):
    """(width, height, RGB bytes) of a PNG, via matplotlib when it is installed."""
    try:
        import matplotlib.image
        import numpy
    except ImportError:
        return read_png_stdlib(path)
    img = matplotlib.image.imread(path)
    if img.ndim == 2:
        img = numpy.stack([img] * 3, axis=-1)
    if img.dtype != numpy.uint8:
        img = numpy.round(img * 255).astype(numpy.uint8)
    return img.shape[1], img.shape[0], numpy.ascontiguousarray(img[:, :, :3]).tobytes()


def colour_stats(rgb):
    """(number of distinct colours, fraction of pixels unlike the most common one)."""
    counts = collections.Counter(rgb[i:i + 3] for i in range(0, len(rgb), 3))
    total = len(rgb) // 3
    return len(counts), 1.0 - counts.most_common(1)[0][1] / total if total else 0.0


def page_message(dom):
    """Text of the viewer's in-page error message when the page made it visible."""
    m = re.search(r'<div id="message"[^>]*style="[^"]*display:\s*block[^"]*"[^>]*>(.*?)</div>', dom, re.S)
    return html.unescape(m.group(1)).strip() if m else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("html", help="generated replay page")
    ap.add_argument("--chromium", help="Chromium binary (default: chromium on PATH)")
    ap.add_argument("--keep", metavar="DIR", help="copy the screenshot and logs into DIR")
    args = ap.parse_args()

    if not os.path.isfile(args.html):
        print("check_replay: FAIL: no such file: %s" % args.html)
        return 1
    chromium = find_chromium(args.chromium)
    if not chromium:
        print("check_replay: Chromium not found (%s); install it with "
              "'apt-get install -y --no-install-recommends chromium'" % (args.chromium or "chromium"))
        return 2

    with tempfile.TemporaryDirectory(prefix="check_replay_") as tmp:
        try:
            rc, dom, stderr, shot = run_chromium(chromium, args.html, tmp)
        except subprocess.TimeoutExpired:
            print("check_replay: FAIL: Chromium did not finish within %d s" % TIMEOUT_S)
            return 1
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
            for name, text in (("chromium_stderr.txt", stderr), ("dom.html", dom)):
                with open(os.path.join(args.keep, name), "w") as f:
                    f.write(text)
            if os.path.isfile(shot):
                shutil.copy(shot, args.keep)

        problems = []
        if rc != 0:
            tail = "\n    ".join(stderr.strip().splitlines()[-5:])
            problems.append("Chromium exited with %d:\n    %s" % (rc, tail))
        for msg in console_messages(stderr):
            problems.append("console: " + msg)
        text = page_message(dom)
        if text:
            problems.append("the page shows its error message: " + text)
        summary = ""
        if not os.path.isfile(shot):
            problems.append("no screenshot was written")
        else:
            w, h, rgb = read_png(shot)
            n_all, changed = colour_stats(rgb)
            r0, r1 = int(h * CANVAS_BAND[0]), int(h * CANVAS_BAND[1])
            n_band, band_changed = colour_stats(rgb[r0 * w * 3:r1 * w * 3])
            if changed < MIN_CHANGED:
                problems.append("screenshot is blank: only %.2f %% of pixels differ from the most "
                                "common colour (need >= %.0f %%)" % (100 * changed, 100 * MIN_CHANGED))
            if n_band < MIN_BAND_COLOURS or band_changed < MIN_BAND_CHANGED:
                problems.append("canvas region (rows %d-%d) looks empty: %d colours, %.2f %% of pixels "
                                "differ from its main colour" % (r0, r1, n_band, 100 * band_changed))
            summary = "%dx%d screenshot, %.1f %% non-background pixels, %d colours in canvas band" % (
                w, h, 100 * changed, n_band)

    if problems:
        print("check_replay: FAIL: %s" % args.html)
        for p in problems:
            print("  - " + p)
        return 1
    print("check_replay: OK: %s: no console messages, %s" % (args.html, summary))
    return 0


if __name__ == "__main__":
    sys.exit(main())
