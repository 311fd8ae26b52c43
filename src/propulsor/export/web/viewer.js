/* propulsor GLB viewer: a small WebGL viewer of the assemblies' GLB files, for a page opened from disk.
 *
 * A page opened from file:// may not fetch() the GLB beside it, so each GLB comes with a classic
 * script (<name>.glb.js) that files its bytes, base64, in window.PROPULSOR_GLB under the script's own
 * URL; the viewer inserts that script when its figure comes into view and reads the bytes from there.
 * It parses the GLB (JSON and BIN chunks), walks the scene's nodes (matrix or TRS), draws every
 * triangle primitive in its material's baseColorFactor with flat Lambert shading (the face normal from
 * the screen-space derivatives of the position), and fits the view to the scene's bounds.
 * Drag: orbit; wheel: zoom; double click: fit again.  Figures: <figure class="viewer" data-models=
 * '[{"script": "...glb.js", "title": "..."}]'> holding a <canvas>, an optional <select>, a status line.
 * State on the figure: data-state = loading | drawn | error (the browser test waits for "drawn").
 */
(function () {
  "use strict";

  function decode64(text) {
    var bin = atob(text), out = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
    return out.buffer;
  }

  // ---- 4x4 matrices, column-major as glTF and WebGL want them
  function ident() { return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]; }
  function mul(a, b) {
    var o = new Array(16);
    for (var c = 0; c < 4; c++)
      for (var r = 0; r < 4; r++) {
        var s = 0;
        for (var k = 0; k < 4; k++) s += a[k * 4 + r] * b[c * 4 + k];
        o[c * 4 + r] = s;
      }
    return o;
  }
  function trs(t, q, s) {
    t = t || [0, 0, 0]; q = q || [0, 0, 0, 1]; s = s || [1, 1, 1];
    var x = q[0], y = q[1], z = q[2], w = q[3];
    return [
      (1 - 2 * (y * y + z * z)) * s[0], 2 * (x * y + z * w) * s[0], 2 * (x * z - y * w) * s[0], 0,
      2 * (x * y - z * w) * s[1], (1 - 2 * (x * x + z * z)) * s[1], 2 * (y * z + x * w) * s[1], 0,
      2 * (x * z + y * w) * s[2], 2 * (y * z - x * w) * s[2], (1 - 2 * (x * x + y * y)) * s[2], 0,
      t[0], t[1], t[2], 1];
  }
  function apply(m, p) {
    return [m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12],
            m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13],
            m[2] * p[0] + m[6] * p[1] + m[10] * p[2] + m[14]];
  }
  function perspective(fovy, aspect, near, far) {
    var f = 1 / Math.tan(fovy / 2), nf = 1 / (near - far);
    return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1, 0, 0, 2 * far * near * nf, 0];
  }
  function lookAt(eye, at, up) {
    var z = norm(sub(eye, at)), x = norm(cross(up, z)), y = cross(z, x);
    return [x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0,
            -dot(x, eye), -dot(y, eye), -dot(z, eye), 1];
  }
  function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
  function norm(a) { var l = Math.sqrt(dot(a, a)) || 1; return [a[0] / l, a[1] / l, a[2] / l]; }

  // ---- GLB
  function parseGLB(buf) {
    var dv = new DataView(buf);
    if (dv.getUint32(0, true) !== 0x46546C67) throw new Error("not a GLB (magic)");
    if (dv.getUint32(4, true) !== 2) throw new Error("GLB version is not 2");
    var off = 12, json = null, bin = null;
    while (off + 8 <= buf.byteLength) {
      var len = dv.getUint32(off, true), type = dv.getUint32(off + 4, true);
      if (type === 0x4E4F534A) json = JSON.parse(new TextDecoder().decode(new Uint8Array(buf, off + 8, len)));
      else if (type === 0x004E4942) bin = buf.slice(off + 8, off + 8 + len);
      off += 8 + len;
    }
    if (!json || !bin) throw new Error("GLB without JSON or BIN chunk");
    return { json: json, bin: bin };
  }

  function accessorArray(g, index) {
    var a = g.json.accessors[index], v = g.json.bufferViews[a.bufferView];
    var n = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4 }[a.type] * a.count;
    var start = (v.byteOffset || 0) + (a.byteOffset || 0);
    var T = { 5126: Float32Array, 5125: Uint32Array, 5123: Uint16Array, 5121: Uint8Array }[a.componentType];
    if (!T) throw new Error("accessor component type " + a.componentType);
    return new T(g.bin, start, n);
  }

  /* Draw items: {matrix, positions, indices, colour} for every primitive of every node of the scene. */
  function drawItems(g) {
    var j = g.json, items = [], scene = j.scenes[j.scene || 0];
    function walk(ni, parent) {
      var n = j.nodes[ni];
      var m = mul(parent, n.matrix ? n.matrix.slice() : trs(n.translation, n.rotation, n.scale));
      if (n.mesh !== undefined)
        j.meshes[n.mesh].primitives.forEach(function (p) {
          if ((p.mode === undefined ? 4 : p.mode) !== 4) return;
          var mat = p.material !== undefined ? j.materials[p.material] : {};
          var pbr = mat.pbrMetallicRoughness || {};
          items.push({ name: n.name || "", matrix: m, positions: accessorArray(g, p.attributes.POSITION),
                       indices: p.indices !== undefined ? accessorArray(g, p.indices) : null,
                       colour: pbr.baseColorFactor || [0.7, 0.7, 0.7, 1] });
        });
      (n.children || []).forEach(function (c) { walk(c, m); });
    }
    scene.nodes.forEach(function (ni) { walk(ni, ident()); });
    return items;
  }

  function bounds(items) {
    var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    items.forEach(function (it) {
      var p = it.positions;
      for (var i = 0; i < p.length; i += 3) {
        var w = apply(it.matrix, [p[i], p[i + 1], p[i + 2]]);
        for (var k = 0; k < 3; k++) { if (w[k] < lo[k]) lo[k] = w[k]; if (w[k] > hi[k]) hi[k] = w[k]; }
      }
    });
    return { lo: lo, hi: hi };
  }

  var VS2 = "#version 300 es\nin vec3 a_pos; uniform mat4 u_model, u_view, u_proj; out vec3 v_eye;\n" +
    "void main() { vec4 e = u_view * u_model * vec4(a_pos, 1.0); v_eye = e.xyz; gl_Position = u_proj * e; }";
  var FS2 = "#version 300 es\nprecision highp float; in vec3 v_eye; uniform vec4 u_colour; out vec4 o;\n" +
    "void main() { vec3 n = normalize(cross(dFdx(v_eye), dFdy(v_eye)));\n" +
    " float d = max(dot(n, normalize(vec3(-0.35, 0.55, 0.76))), 0.0);\n" +
    " o = vec4(u_colour.rgb * (0.32 + 0.68 * d), 1.0); }";
  var VS1 = "attribute vec3 a_pos; uniform mat4 u_model, u_view, u_proj; varying vec3 v_eye;\n" +
    "void main() { vec4 e = u_view * u_model * vec4(a_pos, 1.0); v_eye = e.xyz; gl_Position = u_proj * e; }";
  var FS1 = "#extension GL_OES_standard_derivatives : enable\nprecision highp float; varying vec3 v_eye; uniform vec4 u_colour;\n" +
    "void main() { vec3 n = normalize(cross(dFdx(v_eye), dFdy(v_eye)));\n" +
    " float d = max(dot(n, normalize(vec3(-0.35, 0.55, 0.76))), 0.0);\n" +
    " gl_FragColor = vec4(u_colour.rgb * (0.32 + 0.68 * d), 1.0); }";

  function program(gl, vs, fs) {
    function shader(type, src) {
      var s = gl.createShader(type);
      gl.shaderSource(s, src); gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error("shader: " + gl.getShaderInfoLog(s));
      return s;
    }
    var p = gl.createProgram();
    gl.attachShader(p, shader(gl.VERTEX_SHADER, vs)); gl.attachShader(p, shader(gl.FRAGMENT_SHADER, fs));
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error("program: " + gl.getProgramInfoLog(p));
    return p;
  }

  function Viewer(figure) {
    this.figure = figure;
    this.canvas = figure.querySelector("canvas");
    this.status = figure.querySelector(".status");
    this.models = JSON.parse(figure.getAttribute("data-models"));
    this.select = figure.querySelector("select");
    var gl = this.canvas.getContext("webgl2", { antialias: true, preserveDrawingBuffer: true });
    this.webgl2 = !!gl;
    if (!gl) {
      gl = this.canvas.getContext("webgl", { antialias: true, preserveDrawingBuffer: true });
      if (!gl || !gl.getExtension("OES_standard_derivatives") || !gl.getExtension("OES_element_index_uint"))
        throw new Error("WebGL is not available in this browser");
    }
    this.gl = gl;
    this.prog = this.webgl2 ? program(gl, VS2, FS2) : program(gl, VS1, FS1);
    this.buffers = [];
    this.yaw = Math.PI / 4; this.pitch = Math.asin(1 / Math.sqrt(3)); this.zoom = 1; this.fov = 0.6;
    this.bind();
    if (this.select) this.select.addEventListener("change", this.load.bind(this));
  }

  Viewer.prototype.setState = function (state, text) {
    this.figure.setAttribute("data-state", state);
    if (this.status) this.status.textContent = text;
  };

  Viewer.prototype.load = function () {
    var self = this, model = this.models[this.select ? this.select.selectedIndex : 0];
    this.setState("loading", "loading " + model.title + " …");
    var script = document.createElement("script");
    script.src = model.script;
    script.onload = function () {
      try {
        var b64 = (window.PROPULSOR_GLB || {})[script.src];
        if (!b64) throw new Error(model.script + " did not define its model");
        self.show(parseGLB(decode64(b64)), model);
      } catch (e) {
        self.setState("error", String(e.message || e));
        console.error("propulsor viewer: " + model.script + ": " + (e.message || e));
      }
    };
    script.onerror = function () {
      self.setState("error", "cannot load " + model.script);
      console.error("propulsor viewer: cannot load " + model.script);
    };
    document.head.appendChild(script);
  };

  Viewer.prototype.show = function (glb, model) {
    var gl = this.gl;
    this.buffers.forEach(function (b) { gl.deleteBuffer(b.vbo); gl.deleteBuffer(b.ibo); });
    var items = drawItems(glb);
    this.buffers = items.map(function (it) {
      var vbo = gl.createBuffer(), ibo = gl.createBuffer();
      gl.bindBuffer(gl.ARRAY_BUFFER, vbo); gl.bufferData(gl.ARRAY_BUFFER, it.positions, gl.STATIC_DRAW);
      var idx = it.indices || new Uint32Array(it.positions.length / 3).map(function (_, i) { return i; });
      var wide = idx instanceof Uint32Array;
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ibo); gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, idx, gl.STATIC_DRAW);
      return { vbo: vbo, ibo: ibo, count: idx.length, type: wide ? gl.UNSIGNED_INT : (idx instanceof Uint16Array ? gl.UNSIGNED_SHORT : gl.UNSIGNED_BYTE),
               matrix: it.matrix, colour: it.colour };
    });
    var b = bounds(items);
    this.centre = [0, 1, 2].map(function (k) { return 0.5 * (b.lo[k] + b.hi[k]); });
    this.radius = 0.5 * Math.sqrt(dot(sub(b.hi, b.lo), sub(b.hi, b.lo))) || 1;
    this.box = b;
    this.fit();
    this.setState("drawn", model.title + ": " + items.length + " components; drag to turn, wheel to zoom, double click to fit");
  };

  Viewer.prototype.dir = function () {
    return [Math.cos(this.pitch) * Math.sin(this.yaw), Math.sin(this.pitch), Math.cos(this.pitch) * Math.cos(this.yaw)];
  };

  /* The isometric view again, at the distance where the box's corners fill the canvas (92 %). */
  Viewer.prototype.fit = function () {
    this.yaw = Math.PI / 4; this.pitch = Math.asin(1 / Math.sqrt(3)); this.zoom = 1;
    var back = this.dir(), right = norm(cross([0, 1, 0], back)), up = cross(back, right);
    var c = this.canvas, aspect = (c.clientWidth || 4) / (c.clientHeight || 3), t = Math.tan(this.fov / 2) * 0.92;
    var hw = 0, hh = 0, hd = 0, lo = this.box.lo, hi = this.box.hi, self = this;
    [lo[0], hi[0]].forEach(function (x) { [lo[1], hi[1]].forEach(function (y) { [lo[2], hi[2]].forEach(function (z) {
      var p = sub([x, y, z], self.centre);
      hw = Math.max(hw, Math.abs(dot(p, right))); hh = Math.max(hh, Math.abs(dot(p, up))); hd = Math.max(hd, Math.abs(dot(p, back)));
    }); }); });
    this.dist0 = hd + Math.max(hh / t, hw / (t * aspect), 1e-6);
    this.draw();
  };

  Viewer.prototype.draw = function () {
    var gl = this.gl, c = this.canvas, dpr = window.devicePixelRatio || 1;
    var w = Math.max(1, Math.round(c.clientWidth * dpr)), h = Math.max(1, Math.round(c.clientHeight * dpr));
    if (c.width !== w || c.height !== h) { c.width = w; c.height = h; }
    gl.viewport(0, 0, w, h);
    gl.clearColor(0.96, 0.97, 0.98, 1); gl.enable(gl.DEPTH_TEST); gl.enable(gl.CULL_FACE);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    if (!this.buffers.length) return;
    var fov = this.fov, dist = this.dist0 / this.zoom, dir = this.dir();
    var eye = [this.centre[0] + dist * dir[0], this.centre[1] + dist * dir[1], this.centre[2] + dist * dir[2]];
    var view = lookAt(eye, this.centre, [0, 1, 0]);
    var proj = perspective(fov, w / h, Math.max(dist - 1.5 * this.radius, dist * 0.01), dist + 1.5 * this.radius);
    var p = this.prog;
    gl.useProgram(p);
    gl.uniformMatrix4fv(gl.getUniformLocation(p, "u_view"), false, new Float32Array(view));
    gl.uniformMatrix4fv(gl.getUniformLocation(p, "u_proj"), false, new Float32Array(proj));
    var loc = gl.getAttribLocation(p, "a_pos");
    this.buffers.forEach(function (b) {
      gl.uniformMatrix4fv(gl.getUniformLocation(p, "u_model"), false, new Float32Array(b.matrix));
      gl.uniform4fv(gl.getUniformLocation(p, "u_colour"), new Float32Array(b.colour));
      gl.bindBuffer(gl.ARRAY_BUFFER, b.vbo);
      gl.enableVertexAttribArray(loc); gl.vertexAttribPointer(loc, 3, gl.FLOAT, false, 0, 0);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, b.ibo);
      gl.drawElements(gl.TRIANGLES, b.count, b.type, 0);
    });
  };

  Viewer.prototype.bind = function () {
    var self = this, c = this.canvas, last = null, pending = false;
    function redraw() {
      if (pending) return;
      pending = true;
      requestAnimationFrame(function () { pending = false; self.draw(); });
    }
    c.addEventListener("pointerdown", function (e) { last = [e.clientX, e.clientY]; c.setPointerCapture(e.pointerId); });
    c.addEventListener("pointerup", function () { last = null; });
    c.addEventListener("pointercancel", function () { last = null; });  // a touch that scrolls the page
    c.addEventListener("pointermove", function (e) {
      if (!last) return;
      self.yaw -= (e.clientX - last[0]) * 0.01;
      self.pitch = Math.max(-1.55, Math.min(1.55, self.pitch + (e.clientY - last[1]) * 0.01));
      last = [e.clientX, e.clientY];
      redraw();
    });
    c.addEventListener("wheel", function (e) {
      e.preventDefault();
      self.zoom = Math.max(0.2, Math.min(20, self.zoom * Math.exp(-e.deltaY * 0.001)));
      redraw();
    }, { passive: false });
    c.addEventListener("dblclick", function () { self.fit(); });
    window.addEventListener("resize", redraw);
  };

  function start(figure) {
    try {
      new Viewer(figure).load();
    } catch (e) {
      figure.setAttribute("data-state", "error");
      var s = figure.querySelector(".status");
      if (s) s.textContent = String(e.message || e);
      console.error("propulsor viewer: " + (e.message || e));
    }
  }

  function init() {
    var figures = Array.prototype.slice.call(document.querySelectorAll("figure.viewer"));
    if (!("IntersectionObserver" in window)) { figures.forEach(start); return; }
    var io = new IntersectionObserver(function (entries) {
      entries.forEach(function (en) {
        if (en.isIntersecting) { io.unobserve(en.target); start(en.target); }
      });
    }, { rootMargin: "200px" });
    figures.forEach(function (f) { io.observe(f); });
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", init);
  else init();
})();
