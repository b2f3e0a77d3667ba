'use strict';
// Share links for tapes too big for a URL, through `essi serve`'s share store (docs/cli.md, `essi serve`).
//
// Loaded by index.html after its inline script. When the page is served by `essi serve` (GET /api/health
// answers), sharing a tape bigger than LINK_BYTES uploads it (POST /api/share: stored by SHA-256) and the link is
// `/#share=ID&c=...&l=...&n=NAME`; opening such a link fetches GET /api/share/ID. Without the server (any static
// host) nothing changes: the inline script puts the compressed tape in the URL fragment as before.
(function () {
  const LINK_BYTES = 1 << 20;  // above this, a tape goes to the store (its URL would be hundreds of KB or more)
  let server = null;           // {max_body, ...} once /api/health answered
  const health = fetch('api/health', { cache: 'no-store' })
    .then((r) => (r.ok ? r.json() : null))
    .then((j) => { server = j && j.ok ? j : null; return server; })
    .catch(() => null);

  const useStore = (len) => !!server && len > LINK_BYTES && len <= server.max_body;
  let storeWaiters = [];

  async function upload(name, bytes, query) {
    const res = await fetch('api/share', { method: 'POST', body: bytes, headers: { 'Content-Type': 'application/octet-stream' } });
    const j = await res.json().catch(() => ({}));
    if (!res.ok) throw new Error(j.error || ('HTTP ' + res.status));
    return location.origin + location.pathname + location.search + '#share=' + j.id + '&' + query +
           '&n=' + encodeURIComponent(name);
  }

  // The Share button: index.html's essikitShare(name, ptr, len, query), wrapped.
  const inlineShare = window.essikitShare;
  window.essikitShare = function (name, ptr, len, query) {
    if (!useStore(len)) return inlineShare(name, ptr, len, query);
    const bytes = Module.HEAPU8.slice(ptr, ptr + len);  // copy now: the heap may move
    (async () => {
      let ok = 0, text;
      try {
        text = await upload(name, bytes, query);
        ok = 1;
        history.replaceState(null, '', text);
        try { await navigator.clipboard.writeText(text); } catch (e) { /* the popup shows the link */ }
      } catch (e) {
        text = 'Could not store the tape on the server: ' + e.message;
      }
      Module.ccall('essi_share_done', null, ['number', 'string'], [ok, text]);
      const waiters = storeWaiters;
      storeWaiters = [];
      waiters.forEach((w) => (ok ? w.resolve(text) : w.reject(new Error(text))));
    })();
  };

  // essikit.shareLink() (automation, tests) resolves through the store when the Share button would use it.
  const api = window.essikit;
  if (api && api.shareLink) {
    const inlineLink = api.shareLink.bind(api);
    api.shareLink = function () {
      const s = api.state();
      if (s.status !== 'ready' || !useStore(s.bytes || 0)) return inlineLink();
      return new Promise((resolve, reject) => {
        storeWaiters.push({ resolve, reject });
        Module._essi_share();
      });
    };
    api.shareStore = { ready: health, get server() { return server; }, LINK_BYTES };
  }

  // Opening a stored link: #share=ID[&c=X,Y,ZOOM][&l=LINE][&n=NAME].
  async function openShared() {
    const p = new URLSearchParams(location.hash.slice(1));
    const id = p.get('share');
    if (!id || !api) return;
    await api.ready;
    try {
      const res = await fetch('api/share/' + encodeURIComponent(id));
      if (!res.ok) throw new Error((await res.json().catch(() => ({}))).error || ('HTTP ' + res.status));
      await api.load(p.get('n') || 'shared.esi', new Uint8Array(await res.arrayBuffer()));
      const c = (p.get('c') || '').split(',').map(Number);
      if (c.length === 3 && c.every(Number.isFinite) && c[2] > 0) api.setView(c[0], c[1], c[2]);
      const line = parseInt(p.get('l') || '0', 10);
      if (line > 0) api.selectLine(line);
    } catch (e) {
      console.warn('share link: ' + e.message);
      await api.load('broken-link.txt', new Uint8Array(0));
    }
  }
  let lastShared = '';
  function maybeOpen() {
    const id = new URLSearchParams(location.hash.slice(1)).get('share');
    if (id && id !== lastShared) { lastShared = id; openShared(); }
  }
  window.addEventListener('hashchange', maybeOpen);
  maybeOpen();
})();
