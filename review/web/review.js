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
uniform float wipe; uniform int compare;
out vec4 outColor;
${ocio.text}
vec3 pick(vec4 v) {
  if (channel >= 0) return vec3(v[channel]);
  if (channelCount == 1) return vec3(v.r);
  if (channelCount == 2) return vec3(v.rg, 0.0);
  return v.rgb;
}
void main() {
  ivec2 size = textureSize(imageA, 0);
  vec2 p = (vec2(gl_FragCoord.x, canvasHeight - gl_FragCoord.y) - origin) / zoom;
  ivec2 t = ivec2(floor(p));
  if (t.x < 0 || t.y < 0 || t.x >= size.x || t.y >= size.y) { outColor = vec4(0.12, 0.12, 0.12, 1.0); return; }
  bool useB = compare == 1 && float(t.x) >= wipe * float(size.x);
  vec4 v = useB ? texelFetch(imageB, t, 0) : texelFetch(imageA, t, 0);
  vec4 c = ${ocio.functionName}(vec4(pick(v), 1.0));
  outColor = vec4(clamp(c.rgb, 0.0, 1.0), 1.0);
}`;
}

class Review {
  constructor() {
    this.canvas = $('canvas');
    this.gl = this.canvas.getContext('webgl2', { preserveDrawingBuffer: true, antialias: false });
    if (!this.gl) throw new Error('this browser has no WebGL2');
    this.gl.getExtension('OES_texture_float_linear');
    this.zoom = 1; this.origin = [0, 0];
    this.layers = {};
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
    for (const id of ['exposure', 'gamma', 'channel', 'wipe']) $(id).oninput = () => this.draw();
    $('channel').onchange = () => this.draw();
    $('layer').onchange = () => this.track(() => this.loadLayer());
    $('file').onchange = () => this.track(() => this.loadFile());
    $('compare').onchange = () => this.track(() => this.loadLayer());
    $('actual').onclick = () => { this.zoom = 1; this.origin = [0, 0]; this.draw(); };
    $('fit').onclick = () => this.fit();
    this.canvas.onmousemove = (e) => this.showPixel(e);
    this.canvas.onwheel = (e) => this.zoomAt(e);
    this.canvas.onmousedown = (e) => this.pan(e);
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

  layerInfo(file, name) {
    return this.layers[file + '|' + name];
  }

  async fetchLayer(file, name, info) {
    const key = file + '|' + name;
    if (!this.layers[key]) {
      const bytes = await request('pixels', [file, name]);
      const values = info.format === 'half' ? new Uint16Array(bytes) : new Float32Array(bytes);
      this.layers[key] = { values, info, width: this.image.width, height: this.image.height,
                           texture: this.upload(values, info) };
    }
    return this.layers[key];
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
    gl.uniform1i(u('compare'), this.other ? 1 : 0);
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
    const move = (e) => { this.origin = [origin[0] + e.clientX - start[0], origin[1] + e.clientY - start[1]]; this.draw(); };
    window.addEventListener('mousemove', move);
    window.addEventListener('mouseup', () => window.removeEventListener('mousemove', move), { once: true });
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
