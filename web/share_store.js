'use strict';
// Share links for tapes too big for a URL, through `essi serve`'s share store (docs/cli.md, `essi serve`).
//
// Loaded by index.html after its inline script. When the page is served by `essi serve` (GET /api/health
// answers), sharing a tape bigger than LINK_BYTES uploads it (POST /api/share: stored by SHA-256) and the link is
// `/#share=ID&c=...&l=...&n=NAME`; opening such a link fetches GET /api/share/ID. Without the server (any static
// host) nothing changes: the inline script puts the compressed tape in the URL fragment as before.
(function () {
  const LINK_BYTES = 32 << 10;  // above this, a tape goes to the store (its link would be tens of KB or more)
  let server = null;           // {max_body, ...} once /api/health answered
  const health = fetch('api/health', { cache: 'no-store' })
    .then((r) => (r.ok ? r.json() : null))
    .then((j) => { server = j && j.ok ? j : null; return server; })
    .catch(() => null);

  const useStore = (len) => !!server && len > LINK_BYTES;

  async function upload(name, bytes, query) {
    const res = await fetch('api/share', { method: 'POST', body: bytes, headers: { 'Content-Type': 'application/octet-stream' } });
    const j = await res.json().catch(() => ({}));
    if (!res.ok) throw new Error(j.error || ('HTTP ' + res.status));
    return location.origin + location.pathname + location.search + '#share=' + j.id + '&' + query +
           '&n=' + encodeURIComponent(name);
  }

  // The link for a tape (index.html's essikitMakeLink, wrapped): big tapes go to the store. The Share button
  // and essikit.shareLink() go through it; the rest of sharing stays index.html's.
  const inlineLink = window.essikitMakeLink;
  window.essikitMakeLink = async function (name, bytes, query) {
    if (!useStore(bytes.length)) return inlineLink(name, bytes, query);
    const linkError = window.essikitLinkError;  // (the viewer says it: essi_share_done)
    if (bytes.length > server.max_body)
      throw linkError('store-too-large', (bytes.length / 1048576).toFixed(1), (server.max_body / 1048576).toFixed(0));
    try {
      return await upload(name, bytes, query);
    } catch (e) {
      throw linkError('store-failed', e.message);
    }
  };

  const api = window.essikit;
  if (api) api.shareStore = { ready: health, get server() { return server; }, LINK_BYTES };

  // Opening a stored link: #share=ID[&c=X,Y,ZOOM][&l=LINE][&n=NAME].
  async function openShared() {
    if (!api) return;
    await api.ready;
    try {
      const link = window.essikitParseShare(location.hash);  // (the core's reading of the fragment)
      const linkError = window.essikitLinkError;  // (the viewer says it: essi_link_problem)
      if (!link.share) throw link.problems.length ? linkError('cut', link.problems.join('; ')) : linkError('no-stored-tape');
      let res;
      try {
        res = await fetch('api/share/' + link.share);
      } catch (e) {
        throw linkError('store-down', e.message);
      }
      if (!res.ok) {
        const why = (await res.json().catch(() => ({}))).error || ('HTTP ' + res.status);
        throw linkError(res.status === 404 ? 'gone' : 'store-error', why);
      }
      window.essikitLoadShared(link.name || 'shared.esi', new Uint8Array(await res.arrayBuffer()));
      await api.idle();
      window.essikitApplyShareView(link);
    } catch (e) {
      window.essikitLinkProblem(e);
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
