// femto view's page (docs/viewing.md). It asks the server only for what the
// controls show (one frame, one pixel's bins, one streak slice: float32 from
// /api/renders/...) and exposes it as `femto frames` does (display.cpp):
// linear value x 2^E, clamped, sRGB-encoded, or the false-colour ramp at the
// sRGB encoding of the exposed luminance. The URL's query sets the starting
// state (render, with, compare, bin, steady, exposure, percentile,
// falsecolour, pixel, streak, speed) and follows every change, so a view can
// be bookmarked, and a test can open the page at a chosen frame.
"use strict";
(() => {
  const $ = (id) => document.getElementById(id);
  const MaxDisplay = 512;  // CSS pixels a view may take: small volumes are enlarged by a whole factor
  const FrameCacheBytes = 256 << 20;  // frames kept for scrubbing back and forth
  const ProfileColours = ["#ffb000", "#4fc3f7", "#e57373", "#81c784", "#ba68c8", "#fff176"];
  // display.cpp's false-colour control points (sRGB), linear between them.
  const Ramp = [
    [0.0, [0.0, 0.0, 0.02]], [0.2, [0.2, 0.04, 0.38]], [0.4, [0.53, 0.13, 0.42]],
    [0.6, [0.85, 0.3, 0.25]], [0.8, [0.98, 0.62, 0.05]], [1.0, [0.98, 0.99, 0.75]],
  ];

  const state = {
    renders: [], a: 0, b: 1, compare: "none", bin: 0, steady: false, playing: false, speed: 12,
    mode: "percentile", percentile: 99.5, exposure: 0, falseColour: false,
    pixel: null, streak: "off", streakIndex: 0,
  };
  let pending = 0;         // requests in flight; idle() waits until there are none
  let drawGeneration = 0;  // a draw that a newer one overtook paints nothing
  const frameCache = new Map();
  const percentileCache = new Map();
  let profiles = [];       // [{render, data}] at state.pixel
  let streakCache = { key: "", data: null };

  // ---- numbers to colours ---------------------------------------------------
  const clamp01 = (v) => Math.min(Math.max(v, 0), 1);
  const toSRGB = (v) => (v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055);
  const luminance = (d, i) => 0.2126 * d[i] + 0.7152 * d[i + 1] + 0.0722 * d[i + 2];  // Rec. 709
  function ramp(t) {
    t = Number.isNaN(t) ? 0 : clamp01(t);
    let i = 1;
    while (i + 1 < Ramp.length && t > Ramp[i][0]) ++i;
    const [t0, c0] = Ramp[i - 1], [t1, c1] = Ramp[i];
    const f = (t - t0) / (t1 - t0);
    return c0.map((c, k) => c * (1 - f) + c1[k] * f);
  }

  /// RGBA bytes of `data` (width * height RGB floats) at `exposure` stops.
  function exposed(data, width, height, exposure, falseColour) {
    const image = new ImageData(width, height);
    const out = image.data, scale = Math.pow(2, exposure);
    for (let p = 0, i = 0; p < width * height; ++p, i += 3) {
      let rgb;
      if (falseColour) rgb = ramp(toSRGB(clamp01(luminance(data, i) * scale)));
      else rgb = [0, 1, 2].map((c) => toSRGB(clamp01(data[i + c] * scale)));
      out[4 * p] = Math.round(255 * rgb[0]);
      out[4 * p + 1] = Math.round(255 * rgb[1]);
      out[4 * p + 2] = Math.round(255 * rgb[2]);
      out[4 * p + 3] = 255;
    }
    return image;
  }

  /// The luminance of a minus b: orange where a is brighter, blue where b is,
  /// black where they agree; brightness as the exposed |difference|.
  function difference(a, b, width, height, exposure) {
    const image = new ImageData(width, height);
    const out = image.data, scale = Math.pow(2, exposure);
    for (let p = 0, i = 0; p < width * height; ++p, i += 3) {
      const d = luminance(a, i) - luminance(b, i);
      const t = toSRGB(clamp01(Math.abs(d) * scale));
      const rgb = d >= 0 ? [1, 0.55, 0.1] : [0.25, 0.6, 1];
      out.set([255 * t * rgb[0], 255 * t * rgb[1], 255 * t * rgb[2], 255], 4 * p);
    }
    return image;
  }

  // ---- the server -------------------------------------------------------------
  async function request(url, as) {
    ++pending;
    try {
      const response = await fetch(url);
      if (!response.ok) throw new Error(`${url}: ${response.status} ${(await response.text()).trim()}`);
      return as === "json" ? await response.json() : new Float32Array(await response.arrayBuffer());
    } finally {
      --pending;
    }
  }

  async function frame(render) {
    const key = state.steady ? `${render}/steady` : `${render}/${state.bin}`;
    if (!frameCache.has(key)) {
      const url = `/api/renders/${render}/` + (state.steady ? "steady" : `frame/${state.bin}`);
      frameCache.set(key, request(url).catch((error) => {
        frameCache.delete(key);  // not kept: a later draw asks again
        throw error;
      }));
      const r = state.renders[render], kept = Math.max(2, Math.floor(FrameCacheBytes / (r.width * r.height * 12)));
      while (frameCache.size > Math.min(kept, 256)) frameCache.delete(frameCache.keys().next().value);
    }
    return frameCache.get(key);
  }

  /// The exposure in stops: as set, or the one mapping the percentile of the
  /// shown render's voxel luminance to white (one exposure for the sequence).
  async function exposure() {
    if (state.mode === "set") return state.exposure;
    const key = `${state.a}/${state.percentile}`;
    if (!percentileCache.has(key))
      percentileCache.set(key, request(`/api/renders/${state.a}/percentile?p=${state.percentile}`, "json")
        .catch((error) => {
          percentileCache.delete(key);
          throw error;
        }));
    const { luminance: white } = await percentileCache.get(key);
    const stops = white > 0 ? -Math.log2(white) : 0;
    $("exposure").value = stops.toFixed(2);
    return stops;
  }

  // ---- drawing ----------------------------------------------------------------
  const zoomFor = (r) => Math.max(1, Math.floor(Math.min(MaxDisplay / r.width, MaxDisplay / r.height)));

  function paint(canvas, image, zoomWidth, zoomHeight) {
    canvas.width = image.width;
    canvas.height = image.height;
    canvas.style.width = `${zoomWidth}px`;
    canvas.style.height = `${zoomHeight}px`;
    canvas.getContext("2d").putImageData(image, 0, 0);
  }

  function binLabel(r, bin) {
    if (!r.time) return `bin ${bin} of ${r.bins} (no time axis: the volume has no sidecar .json)`;
    const w = r.time.bin_width, start = r.time.start + bin * w;
    const digits = Math.max(0, Math.ceil(-Math.log10(w)) + 1);
    return `bin ${bin} of ${r.bins}: OPL ${start.toFixed(digits)} to ${(start + w).toFixed(digits)}` +
      ` (centre ${(start + w / 2).toFixed(digits)})`;
  }

  function comparable() {
    const A = state.renders[state.a], B = state.renders[state.b];
    return state.compare !== "none" && B && B !== A && B.width === A.width && B.height === A.height;
  }

  async function draw() {
    const generation = ++drawGeneration;
    const A = state.renders[state.a], B = state.renders[state.b];
    try {
      const stops = await exposure();
      const compare = comparable();
      if (state.compare !== "none" && !compare)
        status(B && B !== A ? `${B.name} is ${B.width}x${B.height}, ${A.name} is ${A.width}x${A.height}: ` +
          "only renders of one size compare" : "pick a second render to compare with");
      else status("");
      // A second render with fewer bins is black past its last one.
      const pastB = !state.steady && compare && state.bin >= B.bins;
      const [dataA, dataB] = await Promise.all([
        frame(state.a), !compare ? null : pastB ? new Float32Array(B.width * B.height * 3) : frame(state.b)]);
      if (generation !== drawGeneration) return;
      const z = zoomFor(A), w = A.width * z, h = A.height * z;
      const time = state.steady ? "steady (sum over all bins)" : binLabel(A, state.bin);
      $("time-label").textContent = time;
      $("figure-b").hidden = !compare || state.compare !== "side";
      if (compare && state.compare === "diff") {
        paint($("view-a"), difference(dataA, dataB, A.width, A.height, stops), w, h);
        $("caption-a").textContent = `${A.name} minus ${B.name} (orange: ${A.name} brighter, blue: ${B.name})`;
      } else {
        paint($("view-a"), exposed(dataA, A.width, A.height, stops, state.falseColour), w, h);
        $("caption-a").textContent = `${A.name}, ${A.width}x${A.height}, ${time}`;
      }
      if (compare && state.compare === "side") {
        paint($("view-b"), exposed(dataB, B.width, B.height, stops, state.falseColour), w, h);
        $("caption-b").textContent = `${B.name}, ${B.bins} bins`;
      }
      const marker = $("marker");
      marker.hidden = !state.pixel;
      if (state.pixel)
        Object.assign(marker.style, { left: `${state.pixel[0] * z}px`, top: `${state.pixel[1] * z}px`,
          width: `${z}px`, height: `${z}px` });
      await drawStreak(stops, generation);
      drawProfile();
    } catch (error) {
      status(String(error.message || error));
    }
    saveQuery();
  }

  async function drawStreak(stops, generation) {
    const A = state.renders[state.a];
    $("figure-streak").hidden = state.streak === "off";
    if (state.streak === "off") return;
    const row = state.streak === "row";
    const limit = row ? A.height : A.width;
    const index = Math.min(Math.max(0, state.streakIndex), limit - 1);
    const key = `${state.a}/${state.streak}/${index}`;
    if (streakCache.key !== key)
      streakCache = { key, data: await request(`/api/renders/${state.a}/streak/${state.streak}/${index}`) };
    if (generation !== drawGeneration) return;
    // Row: x across, time downwards (width x bins); column: time across, y downwards (bins x height).
    const width = row ? A.width : A.bins, height = row ? A.bins : A.height;
    // The spatial axis as in the view; time in at most MaxDisplay / 2 pixels.
    const zt = Math.max(1, Math.floor(MaxDisplay / 2 / A.bins));
    const zx = row ? zoomFor(A) : zt, zy = row ? zt : zoomFor(A);
    paint($("streak"), exposed(streakCache.data, width, height, stops, state.falseColour), width * zx, height * zy);
    $("caption-streak").textContent = row ? `streak at row ${index}: x across, time (bins) downwards`
      : `streak at column ${index}: time (bins) across, y downwards`;
  }

  /// The renders' luminance against time at state.pixel, overlaid: steps at
  /// the bins, against OPL when every render has a time axis (else bin index).
  function drawProfile() {
    const canvas = $("profile"), g = canvas.getContext("2d");
    g.clearRect(0, 0, canvas.width, canvas.height);
    if (!state.pixel || profiles.length === 0) return;
    const byOpl = profiles.every((p) => p.render.time);
    const x0 = (r, b) => (byOpl ? r.time.start + b * r.time.bin_width : b);
    let lo = Infinity, hi = -Infinity, top = 0;
    for (const { render: r, data } of profiles) {
      lo = Math.min(lo, x0(r, 0));
      hi = Math.max(hi, x0(r, r.bins));
      for (let b = 0; b < r.bins; ++b) top = Math.max(top, luminance(data, 3 * b));
    }
    if (!(top > 0)) top = 1;
    const left = 56, right = canvas.width - 8, upper = 8, lower = canvas.height - 28;
    const X = (v) => left + ((v - lo) / (hi - lo)) * (right - left);
    const Y = (v) => lower - (v / top) * (lower - upper);
    g.strokeStyle = "#666";
    g.strokeRect(left, upper, right - left, lower - upper);
    const A = state.renders[state.a];
    if (!state.steady && state.bin < A.bins && profiles.some((p) => p.render === A)) {
      g.fillStyle = "rgba(255,255,255,0.12)";  // the shown bin
      g.fillRect(X(x0(A, state.bin)), upper, Math.max(1, X(x0(A, state.bin + 1)) - X(x0(A, state.bin))), lower - upper);
    }
    g.lineWidth = 2;
    profiles.forEach(({ render: r, data }, k) => {
      g.strokeStyle = ProfileColours[r.index % ProfileColours.length];
      g.beginPath();
      g.moveTo(X(x0(r, 0)), Y(0));
      for (let b = 0; b < r.bins; ++b) {
        const v = Y(luminance(data, 3 * b));
        g.lineTo(X(x0(r, b)), v);
        g.lineTo(X(x0(r, b + 1)), v);
      }
      g.lineTo(X(x0(r, r.bins)), Y(0));
      g.stroke();
      g.fillStyle = g.strokeStyle;
      g.fillText(r.name, right - 160, upper + 14 + 14 * k);
    });
    g.fillStyle = "#aaa";
    g.fillText(top.toPrecision(3), 4, upper + 10);
    g.fillText("0", 4, lower);
    g.fillText(lo.toPrecision(4), left, lower + 16);
    g.fillText(hi.toPrecision(4), right - 40, lower + 16);
    g.fillText(byOpl ? "OPL" : "bin", (left + right) / 2, lower + 16);
    const [x, y] = state.pixel;
    $("caption-profile").textContent = `luminance against time at pixel ${x},${y}` +
      profiles.map((p) => `; ${p.render.name} peaks in bin ${peakBin(p)}`).join("");
  }

  const peakBin = ({ render: r, data }) => {
    let best = 0;
    for (let b = 1; b < r.bins; ++b) if (luminance(data, 3 * b) > luminance(data, 3 * best)) best = b;
    return best;
  };

  /// Every render of the shown one's size, at pixel (x, y).
  async function loadProfiles(x, y) {
    const A = state.renders[state.a];
    state.pixel = [x, y];
    const shown = state.renders.filter((r) => r.width === A.width && r.height === A.height);
    const data = await Promise.all(shown.map((r) => request(`/api/renders/${r.index}/profile/${x}/${y}`)));
    profiles = shown.map((render, k) => ({ render, data: data[k] }));
    await draw();  // outlines the pixel
    saveQuery();
  }

  // ---- controls ---------------------------------------------------------------
  const status = (text) => ($("status").textContent = text);

  function syncControls() {
    const A = state.renders[state.a];
    $("render-a").value = state.a;
    $("render-b").value = state.b;
    $("compare").value = state.compare;
    $("bin").max = A.bins - 1;
    state.bin = Math.min(state.bin, A.bins - 1);
    $("bin").value = state.bin;
    $("bin").disabled = state.steady;
    $("steady").checked = state.steady;
    $("speed").value = state.speed;
    $("play").textContent = state.playing ? "Pause" : "Play";
    $("mode-set").checked = state.mode === "set";
    $("mode-percentile").checked = state.mode === "percentile";
    $("percentile").value = state.percentile;
    $("percentile").disabled = state.mode === "set";
    $("exposure").disabled = state.mode !== "set";
    if (state.mode === "set") $("exposure").value = state.exposure;
    $("false-colour").checked = state.falseColour;
    $("streak-mode").value = state.streak;
    $("streak-index").value = state.streakIndex;
  }

  function saveQuery() {
    const q = new URLSearchParams();
    q.set("render", state.a);
    if (state.compare !== "none") q.set("compare", state.compare), q.set("with", state.b);
    if (state.steady) q.set("steady", 1);
    else q.set("bin", state.bin);
    if (state.mode === "set") q.set("exposure", state.exposure);
    else q.set("percentile", state.percentile);
    if (state.falseColour) q.set("falsecolour", 1);
    if (state.pixel) q.set("pixel", state.pixel.join(","));
    if (state.streak !== "off") q.set("streak", `${state.streak}:${state.streakIndex}`);
    q.set("speed", state.speed);
    history.replaceState(null, "", `?${q}`);
  }

  function readQuery() {
    const q = new URLSearchParams(location.search);
    const int = (name, fallback) => (q.has(name) && Number.isFinite(+q.get(name)) ? Math.round(+q.get(name)) : fallback);
    const n = state.renders.length;
    state.a = Math.min(Math.max(0, int("render", 0)), n - 1);
    state.b = Math.min(Math.max(0, int("with", state.a === 0 && n > 1 ? 1 : 0)), n - 1);
    if (["side", "diff"].includes(q.get("compare"))) state.compare = q.get("compare");
    state.bin = Math.max(0, int("bin", 0));
    state.steady = q.get("steady") === "1";
    if (q.has("exposure") && Number.isFinite(+q.get("exposure"))) state.mode = "set", state.exposure = +q.get("exposure");
    if (q.has("percentile") && +q.get("percentile") >= 0 && +q.get("percentile") <= 100) state.percentile = +q.get("percentile");
    state.falseColour = q.get("falsecolour") === "1";
    state.speed = Math.min(120, Math.max(1, int("speed", state.speed)));
    const streak = /^(row|column):(\d+)$/.exec(q.get("streak") || "");
    if (streak) state.streak = streak[1], state.streakIndex = +streak[2];
    const pixel = /^(\d+),(\d+)$/.exec(q.get("pixel") || "");
    return pixel ? [+pixel[1], +pixel[2]] : null;
  }

  async function play() {
    while (state.playing) {
      const started = performance.now();
      state.bin = (state.bin + 1) % state.renders[state.a].bins;
      syncControls();
      await draw();
      const wait = 1000 / state.speed - (performance.now() - started);
      await new Promise((resolve) => setTimeout(resolve, Math.max(0, wait)));
    }
  }

  function pixelAt(event) {
    const A = state.renders[state.a], rect = event.target.getBoundingClientRect();
    const x = Math.floor(((event.clientX - rect.left) / rect.width) * A.width);
    const y = Math.floor(((event.clientY - rect.top) / rect.height) * A.height);
    return x >= 0 && y >= 0 && x < A.width && y < A.height ? [x, y] : null;
  }

  function onPixelClick(event) {
    const p = pixelAt(event);
    if (!p) return;
    if (state.streak !== "off") {
      state.streakIndex = state.streak === "row" ? p[1] : p[0];
      syncControls();
      draw();
    }
    loadProfiles(p[0], p[1]).catch((e) => status(String(e.message || e)));
  }

  function wire() {
    const redraw = () => (syncControls(), draw());
    $("render-a").onchange = () => {
      state.a = +$("render-a").value;
      if (state.pixel) loadProfiles(...state.pixel).catch((e) => status(String(e.message || e)));
      redraw();
    };
    $("render-b").onchange = () => ((state.b = +$("render-b").value), redraw());
    $("compare").onchange = () => ((state.compare = $("compare").value), redraw());
    $("bin").oninput = () => ((state.bin = +$("bin").value), redraw());
    $("steady").onchange = () => ((state.steady = $("steady").checked), redraw());
    $("speed").onchange = () => ((state.speed = Math.min(120, Math.max(1, +$("speed").value || 12))), redraw());
    $("play").onclick = () => {
      state.playing = !state.playing;
      syncControls();
      if (state.playing) play();
    };
    $("mode-percentile").onchange = $("mode-set").onchange = () => {
      state.mode = $("mode-set").checked ? "set" : "percentile";
      if (state.mode === "set") state.exposure = +$("exposure").value;
      redraw();
    };
    $("percentile").onchange = () => ((state.percentile = clamp01(+$("percentile").value / 100) * 100), redraw());
    $("exposure").onchange = () => ((state.exposure = +$("exposure").value || 0), redraw());
    $("false-colour").onchange = () => ((state.falseColour = $("false-colour").checked), redraw());
    $("streak-mode").onchange = () => ((state.streak = $("streak-mode").value), redraw());
    $("streak-index").onchange = () => ((state.streakIndex = Math.max(0, Math.round(+$("streak-index").value) || 0)), redraw());
    $("view-a").onclick = $("view-b").onclick = onPixelClick;
    document.addEventListener("keydown", (event) => {
      if (event.target.tagName === "INPUT" && event.target.type !== "range") return;
      const bins = state.renders[state.a].bins;
      if (event.key === " ") $("play").click();
      else if (event.key === "ArrowRight" && event.target.id !== "bin") state.bin = (state.bin + 1) % bins, redraw();
      else if (event.key === "ArrowLeft" && event.target.id !== "bin") state.bin = (state.bin + bins - 1) % bins, redraw();
      else return;
      event.preventDefault();
    });
  }

  async function start() {
    state.renders = await request("/api/renders", "json");
    for (const select of [$("render-a"), $("render-b")])
      for (const r of state.renders) select.add(new Option(`${r.index}: ${r.name} (${r.width}x${r.height}, ${r.bins} bins)`, r.index));
    const pixel = readQuery();
    // Without ?bin= the page opens where the light is, not at bin 0 (often black).
    if (!new URLSearchParams(location.search).has("bin") && !state.steady)
      state.bin = (await request(`/api/renders/${state.a}/brightest`, "json")).bin;
    syncControls();
    wire();
    await draw();
    if (pixel) await loadProfiles(...pixel);
  }

  // For scripts and tests driving the page (tests/cli/view_browser_test.py).
  window.femtoView = {
    state,
    /// Resolves once no request is in flight and the last draw has painted.
    idle: async () => {
      for (let quiet = 0; quiet < 3; ) {
        await new Promise((resolve) => setTimeout(resolve, 20));
        quiet = pending === 0 ? quiet + 1 : 0;
      }
    },
    /// The bin where each profiled render's luminance peaks at state.pixel.
    profilePeaks: () => profiles.map((p) => ({ name: p.render.name, bin: peakBin(p) })),
  };
  start().catch((error) => status(String(error.message || error)));
})();
