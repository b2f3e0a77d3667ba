// <essi-viewer>: the essikit viewer (web/, the Dear ImGui WASM program) as a custom element (docs/viewer-element.md).
// The viewer binds window-level events and is one per page, so each element shows it in an <iframe> of its shadow
// root: page/index.html of this package, same origin, driven through the frame's window.essikit (docs/viewer.md).
// `report` is check()'s report of the tape shown (index.js: the CLI's own check, with the viewer's profile).
const kPage = new URL('./page/index.html', import.meta.url);
const kStyle = `
  :host { display: block; position: relative; width: 100%; height: 480px; overflow: hidden; }
  iframe { position: absolute; inset: 0; width: 100%; height: 100%; border: 0; display: block; }
`;

function toBytes(data) {
  if (typeof data === 'string') return new TextEncoder().encode(data);
  if (data instanceof Uint8Array) return data;
  if (data instanceof ArrayBuffer) return new Uint8Array(data);
  if (ArrayBuffer.isView(data)) return new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  throw new TypeError('<essi-viewer>: load() takes a string, a Uint8Array or an ArrayBuffer');
}

// The last part of a URL's path ("plate.esi" of ".../tapes/plate.esi?x=1").
function nameOf(url) {
  const parts = new URL(url, document.baseURI).pathname.split('/');
  return decodeURIComponent(parts[parts.length - 1] || 'tape.esi');
}

export class EssiViewer extends HTMLElement {
  static get observedAttributes() { return ['src', 'profile', 'lang', 'theme']; }

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    const style = document.createElement('style');
    style.textContent = kStyle;
    this._frame = document.createElement('iframe');
    this._frame.title = 'essikit viewer';
    this._frame.src = kPage.href;      // (loaded once the element is in a document)
    root.append(style, this._frame);
    this._report = null;
    this._tape = null;                 // {name, bytes} of the tape shown
    this._queue = Promise.resolve();   // loads and re-checks, one after the other
    this._window = null;               // the frame's window once its viewer runs
    this._started = null;
    this._connected = false;
  }

  connectedCallback() {
    if (this._connected) return;
    this._connected = true;
    if (this.hasAttribute('src')) this._loadSrc(this.getAttribute('src'));
  }

  attributeChangedCallback(name, before, after) {
    // (the attributes the element starts with are read when it is first connected and when the viewer starts)
    if (before === after || !this._connected) return;
    if (name === 'src') {
      if (after) this._loadSrc(after);
    } else if (name === 'theme') {
      if (this._window) this._applyTheme();
    } else {
      this._enqueue(async () => {
        const win = await this._viewer();
        if (name === 'lang') this._applyLanguage();
        else await win.essikit.setProfile(this._profile());
        if (this._tape) await this._recheck();
      });
    }
  }

  /** The check report of the tape shown (`essi check --format json`, as check() gives it); null before a load. */
  get report() { return this._report; }

  /** The frame's automation API (window.essikit of docs/viewer.md) once the viewer runs, else null. */
  get viewer() { return this._window ? this._window.essikit : null; }

  /** Shows a tape (a string, bytes or an ArrayBuffer) named `name`; resolves with its report after essi-load. */
  load(bytes, name = 'tape.esi') {
    const data = toBytes(bytes);
    return this._enqueue(async () => {
      const win = await this._viewer();
      await win.essikit.load(String(name), data);
      this._tape = { name: String(name), bytes: data };
      return this._recheck();
    });
  }

  _enqueue(step) {
    const next = this._queue.then(step);
    this._queue = next.catch(() => {});
    return next;
  }

  _loadSrc(src) {
    const url = new URL(src, document.baseURI);
    this._enqueue(async () => {
      const response = await fetch(url);
      if (!response.ok) throw new Error(`<essi-viewer>: cannot fetch ${url}: HTTP ${response.status}`);
      return new Uint8Array(await response.arrayBuffer());
    }).then((bytes) => this.load(bytes, nameOf(url)))
      .catch((e) => this.dispatchEvent(new CustomEvent('essi-error', { detail: { message: e.message } })));
  }

  _profile() { return this.getAttribute('profile') || 'auto'; }

  // The frame's window once its viewer runs, with the element's attributes applied and the selection hook set.
  _viewer() {
    if (!this._started) {
      this._started = new Promise((resolve, reject) => {
        const ready = () => {
          const doc = this._frame.contentDocument;
          if (!doc || doc.URL !== kPage.href || doc.readyState !== 'complete') return;  // (about:blank, not yet)
          this._frame.removeEventListener('load', ready);
          const win = this._frame.contentWindow;
          if (!win.essikit) return reject(new Error(`<essi-viewer>: ${kPage} is not the essikit viewer`));
          win.essikit.ready.then(async () => {
            this._window = win;
            win.essikitSelected = (line, motion) => this._selected(line, motion);
            this._applyLanguage();
            this._applyTheme();
            await win.essikit.setProfile(this._profile());
            resolve(win);
          }, reject);
        };
        this._frame.addEventListener('load', ready);
        ready();
      });
    }
    return this._started;
  }

  _applyLanguage() {
    const lang = this.getAttribute('lang');
    if (lang) this._window.essikit.setLanguage(lang);
  }

  _applyTheme() {
    const theme = this.getAttribute('theme');
    if (theme) this._window.essikit.setTheme(theme);
  }

  // The report of the tape shown, with the viewer's profile and the element's language; then essi-load.
  async _recheck() {
    const { check } = await import('../index.js');
    const { name, bytes } = this._tape;
    const lang = ['en', 'de', 'zh'].includes(this.getAttribute('lang')) ? this.getAttribute('lang') : 'en';
    this._report = await check(bytes, { name, profile: this._profile(), lang });
    const file = this._report.files[0];
    this.dispatchEvent(new CustomEvent('essi-load', {
      detail: { name, ok: file ? file.ok : false, profile: this._report.profile, summary: this._report.summary },
    }));
    return this._report;
  }

  _selected(line, motion) {
    this.dispatchEvent(new CustomEvent('essi-select', {
      detail: { line: line > 0 ? line : null, motion: motion >= 0 ? motion : null },
    }));
  }
}

if (!customElements.get('essi-viewer')) customElements.define('essi-viewer', EssiViewer);
