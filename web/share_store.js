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
    if (bytes.length > server.max_body) {
      throw new Error('This tape (' + (bytes.length / 1048576).toFixed(1) + ' MB) is larger than this server\'s ' +
                      'share store takes (' + (server.max_body / 1048576).toFixed(0) + ' MB, essi serve --max-body); ' +
                      'send the file instead.');
    }
    try {
      return await upload(name, bytes, query);
    } catch (e) {
      throw new Error('Could not store the tape on the server: ' + e.message);
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
      if (!link.share) throw new Error('This share link is cut off or damaged: ' + (link.problems.join('; ') || 'it names no stored tape'));
      let res;
      try {
        res = await fetch('api/share/' + link.share);
      } catch (e) {
        throw new Error('The share store of this link does not answer (' + e.message + '); is essi serve running?');
      }
      if (!res.ok) {
        const why = (await res.json().catch(() => ({}))).error || ('HTTP ' + res.status);
        throw new Error(res.status === 404 ? 'The tape of this link is no longer stored (shares expire): ' + why
                                           : 'The share store could not give the tape of this link: ' + why);
      }
      window.essikitLoadShared(link.name || 'shared.esi', new Uint8Array(await res.arrayBuffer()));
      await api.idle();
      window.essikitApplyShareView(link);
    } catch (e) {
      window.essikitLinkProblem(e.message);
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
