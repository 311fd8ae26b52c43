/* propulsor's 3D views: the assemblies' GLB files drawn with three.js (vendored: three.min.js, inlined
 * before this script; window.PROPULSOR_THREE), for a page opened from disk.
 *
 * What three.js does: the GLB (GLTFLoader), the drawing (WebGLRenderer, lights, clipping planes), the
 * camera's controls (OrbitControls: left drag turns, right drag / shift+drag / two fingers pan, wheel and
 * pinch zoom toward the cursor), picking (Raycaster) and the motion's poses (AnimationMixer plays the
 * GLB's animation).  What stays ours, because no library does it for this page:
 *  - the GLB's bytes come from a data block of the page (<script type="application/octet-stream">, base64,
 *    never run): a page opened from file:// may not fetch() the GLB beside it, and no file beside the page
 *    is ever run; the bytes are checked before three.js reads them (glbProblem: header, chunks, lists,
 *    no external URI, the nodes a forest, at most MAX_TRIANGLES drawn);
 *  - any number of views on one page: ONE WebGL context (one renderer, its canvas never shown) draws
 *    each view in turn and copies the image into the view's own 2D canvas; a view is loaded when it
 *    comes into sight and drawn only when it changes while in sight; a lost context is waited for,
 *    and every view drawn again when it is restored;
 *  - the tools under a view: the part list (show / hide, colour; a click on a part picks it), the
 *    section plane (x, y or z of the part's frame, and where), the exploded view (components moved
 *    away from the assembly's centre), the motion (a slider through the poses of the GLB's first
 *    animation, one key per pose, and play / pause), a double click fits the view again.
 * Figures: <figure class="viewer" data-models='[{"block": "glb-...", "title": "...", "view": [x, y, z]}]'>
 * ("block": the id of the model's data block; "view": the first camera direction, y up; optional) holding a
 * <canvas>, an optional <select>, a .status line.  data-state = waiting | loading | drawn | error | lost
 * ("drawn" once the image is in the view's canvas).
 */
(function () {
  "use strict";
  var T = window.PROPULSOR_THREE;

  function decode64(text) {
    var bin = atob(text), out = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
    return out.buffer;
  }

  // the limits of a model (policy.py: READ_LIMIT_BYTES["glb"], GLB_JSON_MAX_BYTES, GLB_ITEMS_MAX,
  // GLB_DRAWN_TRIANGLES_MAX; `propulsor check` refuses the same)
  var MAX_GLB_BYTES = 32 * 1048576, MAX_JSON_BYTES = 16 * 1048576, MAX_ITEMS = 10000, MAX_TRIANGLES = 2000000;
  var DATA_TYPE = "application/octet-stream";

  function index(v, n) { return typeof v === "number" && v % 1 === 0 && v >= 0 && v < n; }

  /* Why the GLB in `buf` may not be drawn, or "" : checked before three.js parses a byte of it. */
  function glbProblem(buf) {
    if (buf.byteLength < 20 || buf.byteLength > MAX_GLB_BYTES) return buf.byteLength + " bytes: not a GLB within the limit";
    var dv = new DataView(buf);
    if (dv.getUint32(0, true) !== 0x46546C67 || dv.getUint32(4, true) !== 2) return "not a glTF 2 binary";
    if (dv.getUint32(8, true) !== buf.byteLength) return "its header's length is not its size";
    var n = dv.getUint32(12, true);
    if (dv.getUint32(16, true) !== 0x4E4F534A || n > MAX_JSON_BYTES || n > buf.byteLength - 20) return "no JSON chunk within it";
    var at = 20 + n;
    while (at < buf.byteLength) {
      if (at + 8 > buf.byteLength || dv.getUint32(at, true) > buf.byteLength - at - 8) return "a chunk runs past its end";
      at += 8 + dv.getUint32(at, true);
    }
    var g;
    try { g = JSON.parse(new TextDecoder("utf-8", { fatal: true }).decode(new Uint8Array(buf, 20, n))); }
    catch (e) { return "its JSON does not parse"; }
    if (!g || typeof g !== "object" || Array.isArray(g)) return "its JSON is not an object";
    var keys = ["nodes", "meshes", "accessors", "bufferViews", "buffers", "images", "textures", "materials",
                "scenes", "animations", "samplers", "skins", "cameras"];
    for (var k = 0; k < keys.length; k++) {
      var v = g[keys[k]];
      if (v === undefined) continue;
      if (!Array.isArray(v) || v.length > MAX_ITEMS) return keys[k] + ": not a list of at most " + MAX_ITEMS;
    }
    var uris = (g.buffers || []).concat(g.images || []);
    for (k = 0; k < uris.length; k++) if (!uris[k] || typeof uris[k] !== "object" || "uri" in uris[k]) return "it names an external file";
    var nodes = g.nodes || [], meshes = g.meshes || [], acc = g.accessors || [], parent = [], perMesh = [], prims = 0;
    for (k = 0; k < meshes.length; k++) {
      var p = meshes[k] && meshes[k].primitives, tri = 0;
      if (!Array.isArray(p)) return "meshes[" + k + "] has no list of primitives";
      prims += p.length;
      if (prims > MAX_ITEMS) return "more than " + MAX_ITEMS + " primitives";
      for (var j = 0; j < p.length; j++) {
        var src = p[j] && ("indices" in p[j] ? p[j].indices : p[j].attributes && p[j].attributes.POSITION);
        if (src === undefined) continue;
        if (!index(src, acc.length) || !acc[src] || !index(acc[src].count, 4294967296)) return "a primitive's accessor is not in the file";
        var c = acc[src].count, mode = "mode" in p[j] ? p[j].mode : 4;
        tri += mode === 4 ? Math.floor(c / 3) : (mode === 5 || mode === 6) ? Math.max(c - 2, 0) : c;
      }
      perMesh.push(tri);
    }
    var drawn = 0;
    for (k = 0; k < nodes.length; k++) {
      var node = nodes[k];
      if (!node || typeof node !== "object") return "nodes[" + k + "] is not an object";
      if ("mesh" in node) {
        if (!index(node.mesh, meshes.length)) return "nodes[" + k + "] names no mesh of the file";
        drawn += perMesh[node.mesh];
      }
      var ch = node.children || [];
      if (!Array.isArray(ch)) return "nodes[" + k + "].children is not a list";
      for (j = 0; j < ch.length; j++) {
        if (!index(ch[j], nodes.length) || ch[j] === k || parent[ch[j]] !== undefined) return "its nodes are not a tree";
        parent[ch[j]] = k;
      }
    }
    for (k = 0; k < nodes.length; k++) {  // every node reaches a root within nodes.length steps: no cycle
      for (var up = k, steps = 0; parent[up] !== undefined; up = parent[up]) if (++steps > nodes.length) return "its nodes form a cycle";
    }
    if (drawn > MAX_TRIANGLES) return "it draws " + drawn + " triangles, more than the " + MAX_TRIANGLES + " this view draws";
    return "";
  }

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    Object.keys(attrs || {}).forEach(function (k) { e.setAttribute(k, attrs[k]); });
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // ---- the one renderer every view draws with
  var shared = { renderer: null, lost: false, views: [] };

  function renderer() {
    if (shared.renderer) return shared.renderer;
    var canvas = document.createElement("canvas");
    var r = new T.WebGLRenderer({ canvas: canvas, antialias: true, alpha: false });
    r.localClippingEnabled = true;
    r.toneMapping = T.NoToneMapping;
    canvas.addEventListener("webglcontextlost", function (e) {
      e.preventDefault();  // so that the browser may restore it
      shared.lost = true;
      shared.views.forEach(function (v) { if (v.root) v.setState("lost", "the 3D view waits for the graphics context"); });
    });
    canvas.addEventListener("webglcontextrestored", function () {
      shared.lost = false;
      shared.views.forEach(function (v) { if (v.root) { v.dirty = true; v.schedule(); } });
    });
    shared.renderer = r;
    return r;
  }

  function View(figure) {
    this.figure = figure;
    this.canvas = figure.querySelector("canvas");
    this.status = figure.querySelector(".status");
    this.select = figure.querySelector("select");
    this.models = JSON.parse(figure.getAttribute("data-models"));
    this.visible = false;
    this.root = null;
    this.pending = false;
    shared.views.push(this);
    var self = this;
    this.scene = new T.Scene();
    this.scene.background = new T.Color(0xf5f7fa);
    this.scene.add(new T.HemisphereLight(0xffffff, 0x8a8f96, 1.4));
    this.camera = new T.PerspectiveCamera(35, 4 / 3, 0.001, 100);
    var head = new T.DirectionalLight(0xffffff, 1.6);
    head.position.set(-0.35, 0.55, 0.76);
    this.camera.add(head);
    this.scene.add(this.camera);
    this.controls = new T.OrbitControls(this.camera, this.canvas);
    this.controls.zoomToCursor = true;
    this.controls.screenSpacePanning = true;
    this.controls.addEventListener("change", function () { self.schedule(); });
    this.section = { on: false, axis: 2, at: 0.5 };
    this.plane = new T.Plane(new T.Vector3(0, 0, -1), 0);
    this.explode = 0;
    this.tools = el("div", { class: "tools" });
    this.canvas.insertAdjacentElement("afterend", this.tools);
    this.canvas.addEventListener("dblclick", function () { self.fit(); });
    this.pick();
    if (this.select) this.select.addEventListener("change", function () { self.load(); });
    if ("ResizeObserver" in window) new ResizeObserver(function () { self.schedule(); }).observe(this.canvas);
  }

  View.prototype.setState = function (state, text) {
    this.figure.setAttribute("data-state", state);
    if (this.status) this.status.textContent = text;
  };

  View.prototype.load = function () {
    var self = this, model = this.models[this.select ? this.select.selectedIndex : 0];
    this.setState("loading", "loading " + model.title + " …");
    var block = typeof model.block === "string" ? document.getElementById(model.block) : null;
    if (!block || block.tagName !== "SCRIPT" || block.type !== DATA_TYPE) return self.fail(model.title + ": its model is not on this page");
    var text = block.textContent, buf;
    if (text.length > Math.ceil(MAX_GLB_BYTES / 3) * 4 + 8) return self.fail(model.title + ": its model is larger than " + MAX_GLB_BYTES + " bytes");
    try { buf = decode64(text.trim()); } catch (e) { return self.fail(model.title + ": its model is not base64"); }
    var why = glbProblem(buf);
    if (why) return self.fail(model.title + ": not drawn: " + why);
    try {
      new T.GLTFLoader().parse(buf, "", function (gltf) { self.show(gltf.scene, model, gltf.animations); },
                               function (e) { self.fail(model.title + ": " + (e.message || e)); });
    } catch (e) { self.fail(model.title + ": " + (e.message || e)); }
  };

  View.prototype.fail = function (text) {
    this.setState("error", text);
    console.error("propulsor viewer: " + text);
  };

  /* The assembly: its root node (named as the assembly) holds one node per component. */
  View.prototype.show = function (root, model, clips) {
    var self = this;
    this.stop();
    if (this.root) {
      this.scene.remove(this.root);
      this.root.traverse(function (o) { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); });
    }
    this.root = root;
    this.scene.add(root);
    var top = root.children.length === 1 && !root.children[0].isMesh ? root.children[0] : root;
    this.parts = top.children.slice();
    root.traverse(function (o) {
      if (o.isMesh) {
        o.material.side = T.DoubleSide;  // the inside shows where the section plane cuts
        o.material.clippingPlanes = [self.plane];
      }
    });
    root.updateMatrixWorld(true);
    this.box = new T.Box3().setFromObject(root);
    var centre = this.box.getCenter(new T.Vector3());
    this.parts.forEach(function (p) {
      p.userData.home = p.position.clone();
      var c = new T.Box3().setFromObject(p).getCenter(new T.Vector3());
      // the component's way out in its parent's frame, from the assembly's centre to its own
      var a = p.parent.worldToLocal(centre.clone()), b = p.parent.worldToLocal(c);
      p.userData.away = b.sub(a);
    });
    this.motion = clips && clips.length ? this.motionOf(root, clips[0]) : null;
    this.model = model;
    this.buildTools();
    if (this.motion) this.setFrame(0);
    this.applyExplode();
    this.applySection();
    this.fit();
    this.drawnText = model.title + ": " + this.parts.length + " components; drag to turn, right drag or shift+drag " +
      "to pan, wheel or pinch to zoom, double click to fit";
    this.dirty = true;
    this.schedule();
  };

  /* The isometric view of the whole assembly, filling the canvas. */
  View.prototype.fit = function () {
    if (!this.box) return;
    var centre = this.box.getCenter(new T.Vector3()), r = this.box.getSize(new T.Vector3()).length() / 2 || 1;
    var aspect = (this.canvas.clientWidth || 4) / (this.canvas.clientHeight || 3);
    var half = T.MathUtils.degToRad(this.camera.fov / 2), fit = Math.min(half, Math.atan(Math.tan(half) * aspect));
    var dist = r / Math.sin(fit) * 0.92;
    var d = this.model && this.model.view ? new T.Vector3().fromArray(this.model.view) : new T.Vector3(1, 0.8, 1);
    this.camera.position.copy(centre).add(d.normalize().multiplyScalar(dist));
    this.camera.near = dist / 100; this.camera.far = dist * 10;
    this.controls.target.copy(centre);
    this.controls.update();
    this.schedule();
  };

  View.prototype.schedule = function () {
    var self = this;
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame(function () { self.pending = false; self.draw(); });
  };

  View.prototype.draw = function () {
    if (!this.root || !this.visible || shared.lost) return;
    var r = renderer(), c = this.canvas, dpr = Math.min(window.devicePixelRatio || 1, 2);
    var w = Math.max(1, Math.round(c.clientWidth * dpr)), h = Math.max(1, Math.round(c.clientHeight * dpr));
    if (c.width !== w || c.height !== h) { c.width = w; c.height = h; }
    var size = r.getSize(new T.Vector2());
    if (size.x !== w || size.y !== h) r.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    r.render(this.scene, this.camera);
    var g = r.getContext();
    if (g.isContextLost()) return;
    c.getContext("2d").drawImage(r.domElement, 0, 0);
    if (this.dirty) { this.dirty = false; this.setState("drawn", this.drawnText); }
  };

  // ---- the motion: the GLB's first animation, one key per proof pose (STEP interpolation), played by
  // three's AnimationMixer at the key's own time (so a slider position is exactly one pose)
  View.prototype.motionOf = function (root, clip) {
    var mixer = new T.AnimationMixer(root), action = mixer.clipAction(clip), times = clip.tracks[0].times;
    var extras = clip.userData || {};  // the animation's glTF extras: title, steps, poses
    var step = times.length > 1 ? times[1] - times[0] : 0.06;
    clip.duration = times[times.length - 1] + step;  // the last pose lasts a frame too (never wraps to 0)
    action.play();
    return { mixer: mixer, times: times, step: step, frame: 0, timer: null, clip: clip, extras: extras };
  };

  /* Pose j of the motion: the mixer places the moving components; the exploded view moves them from there. */
  View.prototype.setFrame = function (j) {
    var m = this.motion;
    if (!m) return;
    m.frame = j;
    this.parts.forEach(function (p) { p.position.copy(p.userData.home); });
    m.mixer.setTime(m.times[j]);
    this.parts.forEach(function (p) { p.userData.home = p.position.clone(); });
    this.applyExplode();
    if (m.slider) m.slider.value = String(j);
    if (m.label) m.label.textContent = "pose " + (j + 1) + " of " + m.times.length +
      (m.steps ? " (proof step " + (m.steps[j] + 1) + ")" : "");
    this.schedule();
  };

  View.prototype.play = function () {
    var self = this, m = this.motion;
    if (!m || m.timer) return;
    m.button.textContent = "pause";
    m.timer = setInterval(function () {
      if (!self.visible) return;
      self.setFrame((m.frame + 1) % m.times.length);
    }, Math.max(30, m.step * 1000));
  };

  View.prototype.stop = function () {
    var m = this.motion;
    if (!m || !m.timer) return;
    clearInterval(m.timer);
    m.timer = null;
    m.button.textContent = "play";
  };

  // ---- the tools
  View.prototype.buildTools = function () {
    var self = this, t = this.tools;
    t.textContent = "";
    var list = el("details", { class: "parts" });
    list.appendChild(el("summary", {}, "parts (" + this.parts.length + ")"));
    var ul = el("ul");
    this.rows = [];
    this.parts.forEach(function (p, k) {
      var li = el("li"), box = el("input", { type: "checkbox", "aria-label": "show " + (p.name || "part " + k) });
      box.checked = true;
      box.addEventListener("change", function () { p.visible = box.checked; self.schedule(); });
      var colour = "#888";
      p.traverse(function (o) { if (o.isMesh && colour === "#888") colour = "#" + o.material.color.getHexString(T.SRGBColorSpace); });
      var sw = el("span", { class: "swatch" });
      sw.style.background = colour;
      var label = el("label");
      label.appendChild(box); label.appendChild(sw); label.appendChild(document.createTextNode(p.name || "part " + k));
      li.appendChild(label);
      ul.appendChild(li);
      self.rows.push(li);
    });
    var all = el("button", { type: "button" }, "show all");
    all.addEventListener("click", function () {
      self.parts.forEach(function (p) { p.visible = true; });
      ul.querySelectorAll("input").forEach(function (b) { b.checked = true; });
      self.schedule();
    });
    list.appendChild(ul); list.appendChild(all);
    t.appendChild(list);

    var sec = el("div", { class: "row" });
    var on = el("input", { type: "checkbox", "aria-label": "section plane" });
    var axis = el("select", { "aria-label": "section normal" });
    ["x", "y", "z"].forEach(function (a) { axis.appendChild(el("option", {}, a)); });
    axis.selectedIndex = this.section.axis;
    var at = el("input", { type: "range", min: "0", max: "1000", value: "500", "aria-label": "section position" });
    var secLabel = el("label");
    secLabel.appendChild(on); secLabel.appendChild(document.createTextNode(" section ⟂ "));
    sec.appendChild(secLabel); sec.appendChild(axis); sec.appendChild(at);
    function update() {
      self.section = { on: on.checked, axis: axis.selectedIndex, at: at.value / 1000 };
      self.applySection(); self.schedule();
    }
    [on, axis, at].forEach(function (x) { x.addEventListener("input", update); x.addEventListener("change", update); });
    t.appendChild(sec);

    var m = this.motion;
    if (m) {
      var mo = el("div", { class: "row motion" });
      m.button = el("button", { type: "button", "aria-label": "play the motion" }, "play");
      m.slider = el("input", { type: "range", min: "0", max: String(m.times.length - 1), step: "1", value: "0",
                               "aria-label": "motion pose" });
      m.label = el("span", { class: "pose" });
      m.steps = Array.isArray(m.extras.steps) ? m.extras.steps : null;
      m.title = typeof m.extras.title === "string" ? m.extras.title : "";
      m.button.addEventListener("click", function () { if (m.timer) self.stop(); else self.play(); });
      m.slider.addEventListener("input", function () { self.stop(); self.setFrame(Number(m.slider.value)); });
      var moLabel = el("label", {}, "motion ");
      moLabel.appendChild(m.slider);
      mo.appendChild(m.button); mo.appendChild(moLabel); mo.appendChild(m.label);
      if (m.title) mo.title = m.title;
      t.appendChild(mo);
    }

    if (this.parts.length > 1) {
      var ex = el("div", { class: "row" }), exLabel = el("label", {}, "exploded ");
      var s = el("input", { type: "range", min: "0", max: "1000", value: "0", "aria-label": "exploded view" });
      exLabel.appendChild(s); ex.appendChild(exLabel);
      s.addEventListener("input", function () { self.explode = s.value / 1000; self.applyExplode(); self.schedule(); });
      t.appendChild(ex);
    }
  };

  /* The section plane: normal along the part's x, y or z (in the GLB the part's y is -z, its z is y), at
   * `at` of the assembly's extent along it; three.js cuts away what is at a negative distance from the
   * plane, here the part beyond it. */
  View.prototype.applySection = function () {
    var s = this.section, box = this.box;
    if (!box) return;
    if (!s.on) { this.plane.normal.set(0, 0, 0); this.plane.constant = 1; return; }  // keeps everything
    var n = [new T.Vector3(1, 0, 0), new T.Vector3(0, 0, -1), new T.Vector3(0, 1, 0)][s.axis];
    var lo = Infinity, hi = -Infinity;
    [box.min, box.max].forEach(function (p) { var t = p.dot(n); lo = Math.min(lo, t); hi = Math.max(hi, t); });
    this.plane.normal.copy(n).negate();
    this.plane.constant = lo + s.at * (hi - lo);
  };

  /* Each component moved away from the assembly's centre by `explode` × its own offset × 1.5. */
  View.prototype.applyExplode = function () {
    var f = this.explode * 1.5;
    this.parts.forEach(function (p) {
      p.position.copy(p.userData.home).addScaledVector(p.userData.away, f);
    });
  };

  /* A click (not a drag) on a part: its row in the part list is marked and named on the status line. */
  View.prototype.pick = function () {
    var self = this, down = null, ray = new T.Raycaster();
    this.canvas.addEventListener("pointerdown", function (e) { down = [e.clientX, e.clientY]; });
    this.canvas.addEventListener("pointerup", function (e) {
      if (!down || !self.root || Math.abs(e.clientX - down[0]) + Math.abs(e.clientY - down[1]) > 4) return;
      var b = self.canvas.getBoundingClientRect();
      ray.setFromCamera(new T.Vector2((e.clientX - b.left) / b.width * 2 - 1, 1 - (e.clientY - b.top) / b.height * 2), self.camera);
      var hits = ray.intersectObject(self.root, true).filter(function (h) {
        return self.section.on ? self.plane.distanceToPoint(h.point) >= 0 : true;
      });
      var k = -1;
      if (hits.length) {
        for (var o = hits[0].object; o && k < 0; o = o.parent) k = self.parts.indexOf(o);
      }
      self.rows.forEach(function (r, i) { r.classList.toggle("picked", i === k); });
      if (k >= 0 && self.status) self.status.textContent = "picked: " + (self.parts[k].name || "part " + k);
    });
  };

  function start(figure) {
    try {
      if (!T) throw new Error("the 3D library did not load");
      var v = new View(figure);
      figure.propulsorView = v;
      v.load();
      return v;
    } catch (e) {
      figure.setAttribute("data-state", "error");
      var s = figure.querySelector(".status");
      if (s) s.textContent = String(e.message || e);
      console.error("propulsor viewer: " + (e.message || e));
      return null;
    }
  }

  function init() {
    var figures = Array.prototype.slice.call(document.querySelectorAll("figure.viewer"));
    if (!("IntersectionObserver" in window)) {
      figures.forEach(function (f) { var v = start(f); if (v) v.visible = true; });
      return;
    }
    var io = new IntersectionObserver(function (entries) {
      entries.forEach(function (en) {
        var v = en.target.propulsorView;
        if (!v && en.isIntersecting && !en.target.hasAttribute("data-tried")) {
          en.target.setAttribute("data-tried", "");
          v = start(en.target);
        }
        if (!v) return;
        v.visible = en.isIntersecting;
        if (v.visible) v.schedule();
      });
    }, { rootMargin: "200px" });
    figures.forEach(function (f) { io.observe(f); });
  }

  window.PROPULSOR_VIEWER = { glbProblem: glbProblem };  // the model check, for tests
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", init);
  else init();
})();
