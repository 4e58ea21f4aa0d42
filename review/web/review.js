// The Fluence review page: EXR layers drawn with WebGL2 through the shader OpenColorIO generates
// for the chosen display, view and look (exposure and gamma are its dynamic uniforms). Data come
// from `fluence review`'s server (api/REQUEST?...) or, in a static export, from data.js.
'use strict';

const PARAMETERS = { files: [], image: ['file'], pixels: ['file', 'layer'], menus: ['file'],
                     shader: ['file', 'display', 'view', 'look'] };
const $ = (id) => document.getElementById(id);

function base64Bytes(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

async function request(name, args) {
  const data = window.FLUENCE_REVIEW_DATA;
  if (data) {
    const value = data[[name, ...args].join('|')];
    if (value === undefined) throw new Error('the static export holds no ' + [name, ...args].join(' '));
    return name === 'pixels' ? base64Bytes(value) : value;
  }
  const query = new URLSearchParams();
  PARAMETERS[name].forEach((p, i) => query.set(p, args[i]));
  const response = await fetch('api/' + name + '?' + query);
  if (!response.ok) throw new Error(await response.text());
  return name === 'pixels' ? response.arrayBuffer() : response.json();
}

function halfToFloat(h) {
  const e = (h >> 10) & 31, m = h & 1023, s = h & 32768 ? -1 : 1;
  if (e === 0) return s * m * Math.pow(2, -24);
  if (e === 31) return m ? NaN : s * Infinity;
  return s * (1 + m / 1024) * Math.pow(2, e - 15);
}

const VERTEX = `#version 300 es
in vec2 corner; void main() { gl_Position = vec4(corner, 0.0, 1.0); }`;

function fragmentSource(ocio) {
  return `#version 300 es
precision highp float; precision highp int;
precision highp sampler2D; precision highp sampler3D;
uniform sampler2D imageA; uniform sampler2D imageB;
uniform vec2 origin; uniform float canvasHeight; uniform float zoom; uniform int channel; uniform int channelCount;
uniform float wipe; uniform int mode; uniform sampler2D matte; uniform int showMatte;
out vec4 outColor;
${ocio.text}
vec3 pick(vec4 v) {
  if (channel >= 0) return vec3(v[channel]);
  if (channelCount == 1) return vec3(v.r);
  if (channelCount == 2) return vec3(v.rg, 0.0);
  return v.rgb;
}
vec3 falseColour(float t) {
  t = clamp(t, 0.0, 1.0);
  return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}
void main() {
  ivec2 size = textureSize(imageA, 0);
  vec2 p = (vec2(gl_FragCoord.x, canvasHeight - gl_FragCoord.y) - origin) / zoom;
  ivec2 t = ivec2(floor(p));
  int width = mode == 2 ? 2 * size.x : size.x;
  if (t.x < 0 || t.y < 0 || t.x >= width || t.y >= size.y) { outColor = vec4(0.12, 0.12, 0.12, 1.0); return; }
  bool useB = (mode == 1 && float(t.x) >= wipe * float(size.x)) || (mode == 2 && t.x >= size.x);
  if (mode == 2 && t.x >= size.x) t.x -= size.x;
  if (mode == 3) {
    vec3 d = abs(pick(texelFetch(imageA, t, 0)) - pick(texelFetch(imageB, t, 0)));
    outColor = vec4(falseColour(sqrt(max(d.r, max(d.g, d.b)))), 1.0);
    return;
  }
  vec4 v = useB ? texelFetch(imageB, t, 0) : texelFetch(imageA, t, 0);
  vec4 c = ${ocio.functionName}(vec4(pick(v), 1.0));
  vec3 rgb = clamp(c.rgb, 0.0, 1.0);
  if (showMatte == 1 && !useB) rgb = mix(rgb, vec3(1.0, 0.2, 0.8), 0.6 * texelFetch(matte, t, 0).r);
  outColor = vec4(rgb, 1.0);
}`;
}

class Review {
  constructor() {
    this.canvas = $('canvas');
    this.gl = this.canvas.getContext('webgl2', { preserveDrawingBuffer: true, antialias: false });
    if (!this.gl) throw new Error('this browser has no WebGL2');
    this.gl.getExtension('OES_texture_float_linear');
    this.zoom = 1; this.origin = [0, 0];
    this.layers = new Map();
    this.pending = Promise.resolve();
  }

  // Runs an update after the ones in flight; `pending` settles when all have (tests wait on it).
  track(work) {
    this.pending = this.pending.then(work).catch((e) => this.status(String(e.message || e)));
    return this.pending;
  }

  status(text) { $('status').textContent = text; }

  async start() {
    this.files = (await request('files', [])).files;
    for (const f of this.files) {
      $('file').add(new Option(f.name, f.name));
      $('compare').add(new Option(f.name, f.name));
    }
    $('compare').add(new Option('(none)', ''), 0);
    $('compare').value = '';
    for (const id of ['display', 'view', 'look']) $(id).onchange = () => this.track(() => this.update(id));
    for (const id of ['exposure', 'gamma', 'channel', 'wipe', 'mode']) $(id).oninput = () => this.draw();
    $('mode').onchange = () => this.draw();
    $('reference').replaceChildren(new Option('(none)', ''), ...this.files.map((f) => new Option(f.name, f.name)));
    $('reference').onchange = () => this.track(() => this.showErrors());
    $('play').onclick = () => this.togglePlay();
    $('channel').onchange = () => this.draw();
    $('layer').onchange = () => this.track(() => this.loadLayer());
    $('file').onchange = () => this.track(() => this.loadFile());
    $('compare').onchange = () => this.track(() => this.loadLayer());
    $('actual').onclick = () => { this.zoom = 1; this.origin = [0, 0]; this.draw(); };
    $('fit').onclick = () => this.fit();
    this.canvas.onmousemove = (e) => this.showPixel(e);
    this.canvas.onwheel = (e) => this.zoomAt(e);
    this.canvas.onmousedown = (e) => this.pan(e);
    this.canvas.onclick = (e) => { if (!this.dragged) this.track(() => this.pickMatte(...this.imagePoint(e))); };
    await this.loadFile();
  }

  async loadFile() {
    const file = $('file').value;
    this.image = await request('image', [file]);
    $('layer').replaceChildren(...this.image.layers.map((l) => new Option(l.name, l.name)));
    const menus = await request('menus', [file]);
    this.menus = menus;
    $('display').replaceChildren(...menus.displays.map((d) => new Option(d, d)));
    $('display').value = menus.defaultDisplay;
    $('look').replaceChildren(new Option('(none)', ''), ...menus.looks.map((l) => new Option(l, l)));
    this.fillViews();
    $('metadata').replaceChildren(...Object.entries(this.image.attributes).map(([k, v]) => {
      const row = document.createElement('tr');
      row.insertCell().textContent = k; row.insertCell().textContent = v;
      return row;
    }));
    await this.loadLayer();
    await this.loadShader();
  }

  fillViews() {
    const display = $('display').value;
    $('view').replaceChildren(...this.menus.views[display].map((v) => new Option(v, v)));
    $('view').value = this.menus.defaultViews[display];
  }

  async update(id) {
    if (id === 'display') this.fillViews();
    await this.loadShader();
  }

  // A layer's pixels and texture, kept in a cache of at most `Cache` layers (the oldest not in
  // view leaves first).
  async fetchLayer(file, name, info) {
    const key = file + '|' + name;
    let layer = this.layers.get(key);
    if (!layer) {
      const bytes = await request('pixels', [file, name]);
      const values = info.format === 'half' ? new Uint16Array(bytes) : new Float32Array(bytes);
      layer = { values, info, width: this.image.width, height: this.image.height, texture: this.upload(values, info) };
    }
    this.layers.delete(key);
    this.layers.set(key, layer);
    const limit = Math.max(2, Number($('cache').value) || 2);
    for (const [k, old] of this.layers) {
      if (this.layers.size <= limit) break;
      if (old === this.current || old === this.other || old === layer) continue;
      this.gl.deleteTexture(old.texture);
      this.layers.delete(k);
    }
    return layer;
  }

  // The layer as floats, whatever its stored format.
  floats(layer) {
    return layer.info.format === 'half' ? Float32Array.from(layer.values, halfToFloat) : layer.values;
  }

  upload(values, info) {
    const gl = this.gl, n = info.channels.length;
    const half = info.format === 'half';
    const formats = [gl.RED, gl.RG, gl.RGB, gl.RGBA];
    const internal = half ? [gl.R16F, gl.RG16F, gl.RGB16F, gl.RGBA16F] : [gl.R32F, gl.RG32F, gl.RGB32F, gl.RGBA32F];
    const texture = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, texture);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
    gl.texImage2D(gl.TEXTURE_2D, 0, internal[n - 1], this.image.width, this.image.height, 0, formats[n - 1],
                  half ? gl.HALF_FLOAT : gl.FLOAT, values);
    for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
    return texture;
  }

  async loadLayer() {
    const name = $('layer').value;
    const info = this.image.layers.find((l) => l.name === name);
    this.current = await this.fetchLayer($('file').value, name, info);
    const compare = $('compare').value;
    this.other = compare ? await this.fetchLayer(compare, name, info) : null;
    $('channel').replaceChildren(new Option('all', '-1'), ...info.channels.map((c, i) => new Option(c, String(i))));
    this.draw();
  }

  async loadShader() {
    const ocio = await request('shader', [$('file').value, $('display').value, $('view').value, $('look').value]);
    const gl = this.gl;
    const compile = (type, source) => {
      const shader = gl.createShader(type);
      gl.shaderSource(shader, source);
      gl.compileShader(shader);
      if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
      return shader;
    };
    const program = gl.createProgram();
    gl.attachShader(program, compile(gl.VERTEX_SHADER, VERTEX));
    gl.attachShader(program, compile(gl.FRAGMENT_SHADER, fragmentSource(ocio)));
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
    this.program = program;
    this.ocio = ocio;
    this.lutTextures = ocio.textures.map((t) => this.uploadLut(t));
    this.draw();
  }

  uploadLut(t) {
    const gl = this.gl;
    const texture = gl.createTexture();
    const target = t.depth ? gl.TEXTURE_3D : gl.TEXTURE_2D;
    gl.bindTexture(target, texture);
    const values = new Float32Array(t.values);
    const internal = t.channels === 1 ? gl.R32F : gl.RGB32F, format = t.channels === 1 ? gl.RED : gl.RGB;
    if (t.depth) gl.texImage3D(target, 0, internal, t.width, t.height, t.depth, 0, format, gl.FLOAT, values);
    else gl.texImage2D(target, 0, internal, t.width, t.height, 0, format, gl.FLOAT, values);
    const filter = t.linear ? gl.LINEAR : gl.NEAREST;
    gl.texParameteri(target, gl.TEXTURE_MIN_FILTER, filter);
    gl.texParameteri(target, gl.TEXTURE_MAG_FILTER, filter);
    for (const w of [gl.TEXTURE_WRAP_S, gl.TEXTURE_WRAP_T, gl.TEXTURE_WRAP_R]) gl.texParameteri(target, w, gl.CLAMP_TO_EDGE);
    return { texture, target, sampler: t.samplerName };
  }

  resize() {
    const box = $('viewport');
    this.canvas.width = Math.max(1, box.clientWidth);
    this.canvas.height = Math.max(1, box.clientHeight);
  }

  draw() {
    if (!this.program || !this.current) return;
    const gl = this.gl, program = this.program;
    this.resize();
    gl.viewport(0, 0, this.canvas.width, this.canvas.height);
    gl.useProgram(program);
    const u = (name) => gl.getUniformLocation(program, name);
    gl.activeTexture(gl.TEXTURE0); gl.bindTexture(gl.TEXTURE_2D, this.current.texture);
    gl.uniform1i(u('imageA'), 0);
    gl.activeTexture(gl.TEXTURE1); gl.bindTexture(gl.TEXTURE_2D, (this.other || this.current).texture);
    gl.uniform1i(u('imageB'), 1);
    this.lutTextures.forEach((t, i) => {
      gl.activeTexture(gl.TEXTURE2 + i); gl.bindTexture(t.target, t.texture);
      gl.uniform1i(u(t.sampler), 2 + i);
    });
    gl.uniform2f(u('origin'), this.origin[0], this.origin[1]);
    gl.uniform1f(u('canvasHeight'), this.canvas.height);
    gl.uniform1f(u('zoom'), this.zoom);
    gl.uniform1i(u('channel'), Number($('channel').value || -1));
    gl.uniform1i(u('channelCount'), this.current.info.channels.length);
    gl.uniform1i(u('mode'), this.other ? Number($('mode').value) : 0);
    gl.activeTexture(gl.TEXTURE2 + this.lutTextures.length);
    gl.bindTexture(gl.TEXTURE_2D, this.matte ? this.matte.texture : this.current.texture);
    gl.uniform1i(u('matte'), 2 + this.lutTextures.length);
    gl.uniform1i(u('showMatte'), this.matte && this.matte.file === $('file').value ? 1 : 0);
    gl.uniform1f(u('wipe'), Number($('wipe').value));
    for (const uniform of this.ocio.uniforms) {
      const value = uniform.setting === 'exposure' ? Number($('exposure').value) : 1 / Number($('gamma').value);
      gl.uniform1f(u(uniform.name), value);
    }
    const buffer = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 3, -1, -1, 3]), gl.STATIC_DRAW);
    const corner = gl.getAttribLocation(program, 'corner');
    gl.enableVertexAttribArray(corner);
    gl.vertexAttribPointer(corner, 2, gl.FLOAT, false, 0, 0);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.deleteBuffer(buffer);
  }

  // The displayed 8-bit RGBA of the image's pixels at 1:1 from the top left, rows from the top.
  displayedPixels() {
    const gl = this.gl, w = this.image.width, h = this.image.height;
    this.zoom = 1; this.origin = [0, 0]; this.draw();
    const raw = new Uint8Array(w * h * 4);
    gl.readPixels(0, this.canvas.height - h, w, h, gl.RGBA, gl.UNSIGNED_BYTE, raw);
    const rows = new Uint8Array(w * h * 4);
    for (let y = 0; y < h; ++y) rows.set(raw.subarray((h - 1 - y) * w * 4, (h - y) * w * 4), y * w * 4);
    return rows;
  }

  imagePoint(event) {
    const r = this.canvas.getBoundingClientRect();
    return [Math.floor((event.clientX - r.left - this.origin[0]) / this.zoom),
            Math.floor((event.clientY - r.top - this.origin[1]) / this.zoom)];
  }

  showPixel(event) {
    const [x, y] = this.imagePoint(event);
    const layer = this.current;
    if (!layer || x < 0 || y < 0 || x >= layer.width || y >= layer.height) return;
    const n = layer.info.channels.length, at = (y * layer.width + x) * n;
    const linear = layer.info.channels.map((c, i) => {
      const v = layer.values[at + i];
      return c + ' ' + (layer.info.format === 'half' ? halfToFloat(v) : v).toPrecision(6);
    });
    const r = this.canvas.getBoundingClientRect(), shown = new Uint8Array(4);
    this.gl.readPixels(Math.floor(event.clientX - r.left), this.canvas.height - 1 - Math.floor(event.clientY - r.top),
                       1, 1, this.gl.RGBA, this.gl.UNSIGNED_BYTE, shown);
    $('pixel').textContent = `x ${x} y ${y}\nlinear   ${linear.join('  ')}\ndisplayed ${shown[0]} ${shown[1]} ${shown[2]}`;
  }

  zoomAt(event) {
    event.preventDefault();
    const r = this.canvas.getBoundingClientRect();
    const mx = event.clientX - r.left, my = event.clientY - r.top;
    const factor = event.deltaY < 0 ? 2 : 0.5;
    this.origin = [mx - (mx - this.origin[0]) * factor, my - (my - this.origin[1]) * factor];
    this.zoom *= factor;
    this.draw();
  }

  pan(event) {
    const start = [event.clientX, event.clientY], origin = [...this.origin];
    this.dragged = false;
    const move = (e) => {
      if (Math.abs(e.clientX - start[0]) + Math.abs(e.clientY - start[1]) < 3) return;
      this.dragged = true;
      this.origin = [origin[0] + e.clientX - start[0], origin[1] + e.clientY - start[1]]; this.draw(); };
    window.addEventListener('mousemove', move);
    window.addEventListener('mouseup', () => window.removeEventListener('mousemove', move), { once: true });
  }

  // Cryptomatte: the id covering the most of pixel (x, y) in each Cryptomatte of the image, its name
  // from the manifest, and its matte (the summed coverage of that id) shown over the image.
  async pickMatte(x, y) {
    const file = $('file').value, w = this.image.width, h = this.image.height;
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    for (const crypto of this.image.cryptomatte) {
      const ranks = this.image.layers.filter((l) => new RegExp('^' + crypto.name + '\\d\\d$').test(l.name));
      const layers = await Promise.all(ranks.map((l) => this.fetchLayer(file, l.name, l)));
      const bits = (v) => new Uint32Array(new Float32Array([v]).buffer)[0];
      const coverage = new Map();
      for (const l of layers) {
        const v = this.floats(l), at = (y * w + x) * 4;
        for (const k of [0, 2]) coverage.set(bits(v[at + k]), (coverage.get(bits(v[at + k])) || 0) + v[at + k + 1]);
      }
      let best = null;
      for (const [id, c] of coverage) if (c > 0 && (best === null || c > coverage.get(best))) best = id;
      if (best === null) continue;
      const hex = best.toString(16).padStart(8, '0');
      const name = Object.entries(JSON.parse(crypto.manifest || '{}')).find(([, v]) => v === hex)?.[0] || hex;
      const matte = new Float32Array(w * h);
      for (const l of layers) {
        const v = this.floats(l);
        for (let p = 0; p < w * h; ++p)
          for (const k of [0, 2]) if (bits(v[p * 4 + k]) === best) matte[p] += v[p * 4 + k + 1];
      }
      const gl = this.gl, texture = gl.createTexture();
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32F, w, h, 0, gl.RED, gl.FLOAT, matte);
      for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
      if (this.matte) gl.deleteTexture(this.matte.texture);
      this.matte = { file, name, texture };
      $('matte').textContent = crypto.name + ': ' + name;
      this.draw();
      return;
    }
    $('matte').textContent = 'no Cryptomatte id at ' + x + ', ' + y;
  }

  // relMSE of every image's beauty against the chosen reference: the mean over pixels and RGB of
  // (X - R)^2 / (R^2 + 0.01) (bench/fluence_bench/metrics.py without its noise correction), and
  // the error-against-time chart (fluence/renderSeconds); clicking a point shows that image.
  async showErrors() {
    const reference = $('reference').value;
    $('errors').replaceChildren();
    $('chart')?.remove();
    if (!reference) return;
    const rgbOf = async (file) => {
      const image = await request('image', [file]);
      const info = image.layers.find((l) => l.name === 'rgba');
      const layer = await this.fetchLayer(file, 'rgba', info);
      return { image, values: this.floats(layer), n: info.channels.length };
    };
    const ref = await rgbOf(reference);
    const points = [];
    for (const f of this.files) {
      if (f.name === reference) continue;
      const x = await rgbOf(f.name);
      if (x.image.width !== ref.image.width || x.image.height !== ref.image.height) continue;
      let sum = 0;
      const pixels = ref.image.width * ref.image.height;
      for (let p = 0; p < pixels; ++p)
        for (let c = 0; c < 3; ++c) {
          const r = ref.values[p * ref.n + c], d = x.values[p * x.n + c] - r;
          sum += (d * d) / (r * r + 0.01);
        }
      const relmse = sum / (pixels * 3);
      points.push({ name: f.name, relmse, seconds: Number(x.image.attributes['fluence/renderSeconds']) });
      const row = document.createElement('tr');
      row.insertCell().textContent = f.name;
      row.insertCell().textContent = relmse.toPrecision(4);
      row.onclick = () => this.show(f.name);
      $('errors').append(row);
    }
    this.chart(points.filter((p) => p.seconds > 0 && p.relmse > 0));
  }

  chart(points) {
    if (points.length === 0) return;
    const svg = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
    svg.id = 'chart';
    svg.setAttribute('viewBox', '0 0 300 200');
    const lx = points.map((p) => Math.log10(p.seconds)), ly = points.map((p) => Math.log10(p.relmse));
    const span = (v) => [Math.min(...v), Math.max(...v) - Math.min(...v) || 1];
    const [x0, dx] = span(lx), [y0, dy] = span(ly);
    svg.innerHTML = '<text x="150" y="196" fill="#aaa" font-size="10" text-anchor="middle">time (s, log)</text>' +
                    '<text x="4" y="10" fill="#aaa" font-size="10">relMSE (log)</text>';
    points.forEach((p, i) => {
      const dot = document.createElementNS(svg.namespaceURI, 'circle');
      dot.setAttribute('cx', 20 + 260 * (lx[i] - x0) / dx);
      dot.setAttribute('cy', 180 - 160 * (ly[i] - y0) / dy);
      dot.setAttribute('r', 4);
      dot.setAttribute('fill', '#4af');
      dot.innerHTML = '<title>' + p.name + ' ' + p.seconds + ' s, relMSE ' + p.relmse.toPrecision(4) + '</title>';
      dot.onclick = () => this.show(p.name);
      svg.append(dot);
    });
    $('errors').after(svg);
  }

  show(file) {
    $('file').value = file;
    return this.track(() => this.loadFile());
  }

  // The flipbook: plays the current image's sequence at `fps`, each frame's layer preloaded (the
  // layer cache holds up to `Cache` of them); a frame not loaded in time is shown late, not skipped.
  togglePlay() {
    if (this.playing) { this.playing = false; $('play').textContent = 'Play'; return; }
    const sequence = this.files.find((f) => f.name === $('file').value)?.sequence;
    const frames = this.files.filter((f) => sequence && f.sequence === sequence);
    if (frames.length < 2) { this.status('the image is not a frame of a sequence'); return; }
    this.playing = true;
    $('play').textContent = 'Stop';
    const layerName = $('layer').value, info = this.image.layers.find((l) => l.name === layerName);
    const fps = Math.max(1, Number($('fps').value) || 24), start = performance.now();
    const preload = frames.slice(0, Math.max(2, Number($('cache').value) - 2))
                          .map((f) => this.fetchLayer(f.name, layerName, info));
    const tick = async () => {
      if (!this.playing) return;
      await Promise.all(preload);
      const index = Math.floor((performance.now() - start) / 1000 * fps) % frames.length;
      this.current = await this.fetchLayer(frames[index].name, layerName, info);
      $('file').value = frames[index].name;
      this.status('frame ' + frames[index].frame + ' (' + fps + ' fps)');
      this.draw();
      requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
  }

  fit() {
    const box = $('viewport');
    this.zoom = Math.min(box.clientWidth / this.image.width, box.clientHeight / this.image.height);
    this.origin = [0, 0];
    this.draw();
  }
}

window.fluenceReview = new Review();
window.fluenceReviewReady = window.fluenceReview.start().catch((e) => {
  window.fluenceReview.status(String(e.message || e));
  throw e;
});
window.addEventListener('resize', () => window.fluenceReview.draw());
