#!/usr/bin/python3
"""`femto view` driven in a real browser: headless Chromium from Debian.

  view_browser_test.py FEMTO WORKDIR [SCREENSHOT]

Writes two tiny float32 volumes with one hot voxel each (same pixel,
different bins) and a sparse 12.9 GB one, starts `femto view a.npy b.npy
large.npy --no-browser` on a free port
of 127.0.0.1 and drives the page through Chromium's DevTools protocol over a
pipe (--remote-debugging-pipe: JSON messages separated by NUL bytes on file
descriptors 3 and 4; Python's standard library only). It moves the time
slider to the hot bin and checks the screenshot: bright at the hot voxel,
dark elsewhere (and dark there in another bin); clicks the hot pixel and
checks each render's plotted profile peaks at its own hot bin; checks the
difference view; and that requests for anything not named on the command
line get 404, and that the large volume is served at once. SCREENSHOT, when given, receives a screenshot for the docs.
Exits 77 (skipped) when chromium is not installed.
"""
import base64
import json
import os
import select
import signal
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request
import zlib

FEMTO, WORK = sys.argv[1:3]
DOCS_SCREENSHOT = sys.argv[3] if len(sys.argv) > 3 else None
H, W, BINS = 5, 7, 9
HOT_Y, HOT_X = 3, 2
HOT_BIN_A, HOT_BIN_B = 6, 2
TIMEOUT = 30.0  # seconds for any one wait; the whole test takes a few
failures = []
checks = 0


def check(condition, message):
    global checks
    checks += 1
    if not condition:
        failures.append(message)
        print("FAIL:", message, flush=True)


def find_chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def write_volume(path, hot_bin, start_opl):
    """A black (H, W, BINS, 3) float32 .npy with one white voxel, and its sidecar."""
    header = "{'descr': '<f4', 'fortran_order': False, 'shape': (%d, %d, %d, 3), }" % (H, W, BINS)
    header += " " * ((64 - (10 + len(header) + 1) % 64) % 64) + "\n"
    data = bytearray(H * W * BINS * 3 * 4)
    offset = (((HOT_Y * W + HOT_X) * BINS) + hot_bin) * 3 * 4
    data[offset:offset + 12] = struct.pack("<3f", 1.0, 1.0, 1.0)
    with open(path, "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + data)
    with open(path[:-4] + ".json", "w") as f:
        json.dump({"format": "femto transient volume", "version": 1, "width": W, "height": H, "bins": BINS,
                   "time_unit": "opl", "start_opl": start_opl, "bin_width_opl": 0.5,
                   "end_opl": start_opl + 0.5 * BINS}, f)


def read_png(data):
    """An 8-bit RGB or RGBA PNG (as Chromium writes) -> (width, height, channels, rows of bytes)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), (depth, colour)
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        filt, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):  # undo the PNG filters (PNG spec section 9)
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if filt == 1:
                line[i] = (line[i] + a) & 255
            elif filt == 2:
                line[i] = (line[i] + b) & 255
            elif filt == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif filt == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


class Browser:
    """Headless Chromium spoken to over --remote-debugging-pipe, one page attached."""

    def __init__(self, chromium, profile_dir):
        to_child_r, self.to_child = os.pipe()
        self.from_child, from_child_w = os.pipe()

        def wire_fds():  # the child reads commands on fd 3 and answers on fd 4
            r, w = os.dup(to_child_r), os.dup(from_child_w)
            os.dup2(r, 3)
            os.dup2(w, 4)

        self.process = subprocess.Popen(
            [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe",
             "--no-first-run", "--no-default-browser-check", "--disable-extensions", "--mute-audio",
             "--hide-scrollbars", f"--user-data-dir={profile_dir}", "--window-size=1300,1000",
             "--force-device-scale-factor=1", "about:blank"],
            pass_fds=(3, 4), preexec_fn=wire_fds, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            start_new_session=True)  # its own process group: close() reaps its helpers too
        os.close(to_child_r)
        os.close(from_child_w)
        self.buffer, self.next_id, self.session = b"", 0, None
        target = self.call("Target.createTarget", url="about:blank")["targetId"]
        self.session = self.call("Target.attachToTarget", targetId=target, flatten=True)["sessionId"]

    def call(self, method, **params):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params}
        if self.session and not method.startswith("Target."):
            message["sessionId"] = self.session
        os.write(self.to_child, json.dumps(message).encode() + b"\0")
        deadline = time.monotonic() + TIMEOUT
        while True:
            while b"\0" in self.buffer:
                text, self.buffer = self.buffer.split(b"\0", 1)
                reply = json.loads(text)
                if reply.get("id") == self.next_id:
                    if "error" in reply:
                        raise RuntimeError(f"{method}: {reply['error']}")
                    return reply["result"]
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.from_child], [], [], left)[0]:
                raise RuntimeError(f"{method}: no answer from chromium in {TIMEOUT} s")
            chunk = os.read(self.from_child, 1 << 20)
            if not chunk:
                raise RuntimeError(f"{method}: chromium closed the pipe")
            self.buffer += chunk

    def evaluate(self, expression):
        """The value of a JS expression (awaited if a promise)."""
        result = self.call("Runtime.evaluate", expression=expression, awaitPromise=True, returnByValue=True)
        if "exceptionDetails" in result:
            raise RuntimeError(f"{expression}: {result['exceptionDetails']}")
        return result["result"].get("value")

    def open(self, url):
        self.call("Page.enable")
        self.call("Page.navigate", url=url)
        deadline = time.monotonic() + TIMEOUT
        while not self.evaluate("!!(window.femtoView && window.femtoView.state.renders.length)"):
            if time.monotonic() > deadline:
                raise RuntimeError(f"the page at {url} did not load its renders")
            time.sleep(0.05)
        self.evaluate("femtoView.idle()")

    def screenshot(self):
        return base64.b64decode(self.call("Page.captureScreenshot", format="png")["data"])

    def click(self, x, y):
        for kind in ("mousePressed", "mouseReleased"):
            self.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, button="left", clickCount=1)

    def close(self):
        """Ends Chromium and every process it started (zygote, renderers,
        GPU and network services), so none still writes to the profile
        folder when the caller removes it (the clean-up race seen under load)."""
        try:
            self.call("Browser.close")
        except (RuntimeError, OSError):
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            pass
        try:
            os.killpg(self.process.pid, signal.SIGKILL)  # helpers left behind, if any
        except ProcessLookupError:
            pass
        if self.process.poll() is None:
            self.process.wait()
        deadline = time.time() + TIMEOUT
        while time.time() < deadline and group_alive(self.process.pid):
            time.sleep(0.05)


def group_alive(pgid):
    """Whether any process of group `pgid` is still running (zombies aside)."""
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == pgid and fields[0] != "Z":
            return True
    return False


def write_sparse_volume(path, height, width, bins):
    """A black volume as a sparse file: its size, none of its disk blocks."""
    header = "{'descr': '<f4', 'fortran_order': False, 'shape': (%d, %d, %d, 3), }" % (height, width, bins)
    header += " " * ((64 - (10 + len(header) + 1) % 64) % 64) + "\n"
    with open(path, "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode())
        f.truncate(10 + len(header) + height * width * bins * 12)


def start_viewer(volumes):
    """`femto view` on a free port; returns (process, base URL) from its first line."""
    process = subprocess.Popen([FEMTO, "view", *volumes, "--no-browser"], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    if not select.select([process.stdout], [], [], TIMEOUT)[0]:
        process.kill()
        raise RuntimeError("femto view printed no URL")
    line = process.stdout.readline()
    check(line.startswith("femto view: http://127.0.0.1:"), f"femto view's first line: {line!r}")
    return process, line.split()[2]


def resident_file_kib(pid):
    """The file-backed pages of a process's memory now (RssFile, KiB)."""
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("RssFile:"):
                return int(line.split()[1])
    raise RuntimeError("no RssFile in /proc/<pid>/status")


def status_of(url, method="GET"):
    try:
        with urllib.request.urlopen(urllib.request.Request(url, method=method, data=b"" if method != "GET" else None),
                                    timeout=TIMEOUT) as response:
            return response.status
    except urllib.error.HTTPError as e:
        return e.code


def canvas_pixel(browser, canvas_id, x, y, width=W, height=H):
    """The screenshot coordinates of the centre of pixel (x, y) of a canvas showing width x height pixels."""
    rect = browser.evaluate(f"(() => {{ const r = document.getElementById('{canvas_id}').getBoundingClientRect();"
                            " return [r.left, r.top, r.width, r.height]; })()")
    return (rect[0] + (x + 0.5) * rect[2] / width, rect[1] + (y + 0.5) * rect[3] / height)


def pixel_of(png, point):
    width, height, channels, rows = png
    x, y = int(point[0]), int(point[1])
    return tuple(rows[y][x * channels:x * channels + 3])


def main():
    chromium = find_chromium()
    if not chromium:
        print("chromium is not installed (Debian: apt-get install chromium): skipped")
        return 77
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    a, b = os.path.join(WORK, "a.npy"), os.path.join(WORK, "b.npy")
    write_volume(a, HOT_BIN_A, 3.0)
    write_volume(b, HOT_BIN_B, 3.0)
    with open(os.path.join(WORK, "secret.txt"), "w") as f:
        f.write("not for the viewer\n")

    # 512 x 512 x 4096 bins = 12.9 GB: opened by memory map, so the viewer
    # starts and serves a frame without reading the volume.
    large = os.path.join(WORK, "large.npy")
    write_sparse_volume(large, 512, 512, 4096)
    viewer, base = start_viewer([a, b, large])
    browser = None
    try:
        # Counted in memory, not seconds (load stretches time, not work): the
        # frame is 512 x 512 pages of the map, 1 GiB at most with the headers,
        # while reading the volume would page in 12.9 GB.
        check(status_of(base + "api/renders/2/frame/4000") == 200, "a frame of the 12.9 GB volume is served")
        resident = resident_file_kib(viewer.pid)
        print(f"12.9 GB volume: a frame served with {resident / 1024:.0f} MiB of file pages resident")
        check(resident < 3 * 1024 * 1024, f"the 12.9 GB volume is mapped, not read: {resident} KiB of file pages resident")
        # Only the named renders, by index; nothing else, no writes.
        check(status_of(base + "api/renders/0/frame/0") == 200, "frame 0 of render 0 is served")
        for path in ("api/renders/3/frame/0", "secret.txt", "a.npy", "../secret.txt", "%2e%2e/secret.txt",
                     "api/renders/0/../../secret.txt", "api/files/secret.txt"):
            check(status_of(base + path) == 404, f"{path} is 404")
        check(status_of(base + "api/renders", "POST") == 404, "POST is 404")

        with tempfile.TemporaryDirectory(dir=WORK, ignore_cleanup_errors=True) as profile:
            browser = Browser(chromium, profile)
            try:
                # Start in a dark bin with a fixed exposure (0 stops: the hot voxel, 1.0, is white).
                browser.open(base + "?render=0&bin=0&exposure=0")
                hot = canvas_pixel(browser, "view-a", HOT_X, HOT_Y)
                cold = canvas_pixel(browser, "view-a", HOT_X + 2, HOT_Y - 1)
                shot = read_png(browser.screenshot())
                check(max(pixel_of(shot, hot)) < 30, f"bin 0: the hot pixel is dark, got {pixel_of(shot, hot)}")

                # Move the time slider to the hot bin as a person would: it fires 'input'.
                browser.evaluate(f"(() => {{ const s = document.getElementById('bin'); s.value = {HOT_BIN_A};"
                                 " s.dispatchEvent(new Event('input')); })()")
                browser.evaluate("femtoView.idle()")
                shot = read_png(browser.screenshot())
                check(min(pixel_of(shot, hot)) > 225, f"bin {HOT_BIN_A}: the hot pixel is bright, got {pixel_of(shot, hot)}")
                check(max(pixel_of(shot, cold)) < 30, f"bin {HOT_BIN_A}: another pixel is dark, got {pixel_of(shot, cold)}")
                label = browser.evaluate("document.getElementById('time-label').textContent")
                check(label.startswith(f"bin {HOT_BIN_A} of {BINS}: OPL 6.00 to 6.50"), f"time label: {label!r}")

                # Click the hot pixel: both renders' profiles, each peaking at its own hot bin.
                browser.click(*hot)
                browser.evaluate("femtoView.idle()")
                peaks = browser.evaluate("femtoView.profilePeaks()")
                check(peaks == [{"name": "a.npy", "bin": HOT_BIN_A}, {"name": "b.npy", "bin": HOT_BIN_B}],
                      f"profile peaks after clicking the hot pixel: {peaks}")
                caption = browser.evaluate("document.getElementById('caption-profile').textContent")
                check(f"pixel {HOT_X},{HOT_Y}" in caption, f"profile caption: {caption!r}")

                # Play advances the bin by itself; Pause stops it.
                browser.evaluate("document.getElementById('play').click()")
                time.sleep(1.0)
                browser.evaluate("document.getElementById('play').click()")
                browser.evaluate("femtoView.idle()")
                moved = browser.evaluate("femtoView.state.bin")
                check(moved != HOT_BIN_A, f"Play moved the bin on from {HOT_BIN_A}: now {moved}")
                time.sleep(0.3)
                check(browser.evaluate("femtoView.state.bin") == moved, "Pause stopped the playback")

                # The default exposure (99.5th percentile of non-black voxels: here
                # the hot voxel itself) shows the hot voxel white, to the histogram's 2 %.
                browser.open(base + f"?render=0&bin={HOT_BIN_A}")
                hot = canvas_pixel(browser, "view-a", HOT_X, HOT_Y)
                stops = float(browser.evaluate("document.getElementById('exposure').value"))
                check(abs(stops) < 0.05, f"percentile exposure of a single white voxel: {stops} stops, expected about 0")
                check(min(pixel_of(read_png(browser.screenshot()), hot)) > 225, "percentile exposure: the hot pixel is white")

                # The difference a - b in bin HOT_BIN_B: b is brighter there (blue), a is black.
                browser.open(base + f"?render=0&with=1&compare=diff&bin={HOT_BIN_B}&exposure=0")
                hot = canvas_pixel(browser, "view-a", HOT_X, HOT_Y)
                r, g, b_ = pixel_of(read_png(browser.screenshot()), hot)
                check(b_ > 200 and r < 120, f"difference where b is brighter: blue expected, got {(r, g, b_)}")

                # Side by side with the row's streak image, in false colour: the
                # state the docs' screenshot shows (the page is taller than the window).
                browser.call("Emulation.setDeviceMetricsOverride", width=1300, height=940, deviceScaleFactor=1,
                             mobile=False)
                browser.open(base + f"?render=0&with=1&compare=side&bin={HOT_BIN_A}&exposure=0&falsecolour=1"
                             f"&pixel={HOT_X},{HOT_Y}&streak=row:{HOT_Y}")
                png = browser.screenshot()
                shot = read_png(png)
                hot_a, hot_b = canvas_pixel(browser, "view-a", HOT_X, HOT_Y), canvas_pixel(browser, "view-b", HOT_X, HOT_Y)
                check(min(pixel_of(shot, hot_a)) > 180, f"side by side: a's hot pixel is bright, got {pixel_of(shot, hot_a)}")
                check(max(pixel_of(shot, hot_b)) < 30, f"side by side: b is dark in bin {HOT_BIN_A}, got {pixel_of(shot, hot_b)}")
                # Row HOT_Y's streak image: x across, bins downwards, bright only at (HOT_X, HOT_BIN_A).
                for x, bin_, bright in ((HOT_X, HOT_BIN_A, True), (HOT_X, HOT_BIN_B, False), (HOT_X + 1, HOT_BIN_A, False)):
                    value = pixel_of(shot, canvas_pixel(browser, "streak", x, bin_, W, BINS))
                    check((min(value) > 180) if bright else (max(value) < 30),
                          f"streak at row {HOT_Y}, x {x}, bin {bin_}: {'bright' if bright else 'dark'} expected, got {value}")
                if DOCS_SCREENSHOT:
                    with open(DOCS_SCREENSHOT, "wb") as f:
                        f.write(png)
            finally:
                browser.close()  # before the profile folder goes
                browser = None
    finally:
        if browser:
            browser.close()
        viewer.terminate()
        viewer.wait(timeout=10)
        os.remove(large)  # sparse, but 12.9 GB to any tool that copies it

    print(f"{checks - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
