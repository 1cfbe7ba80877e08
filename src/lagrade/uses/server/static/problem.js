// The problem page's script (served from this server, /static/problem.js: the page's
// Content-Security-Policy allows no inline script). The "read as" preview of each typed part,
// scrollable boxes reachable by keyboard, and, after a check, focus on the result, announced.
(function () {
  var form = document.getElementById('answer');
  if (!form) return;
  var csrf = form.getAttribute('data-csrf'), pid = form.getAttribute('data-pid'), timers = {};
  function value(box) {
    var shape = box.getAttribute('data-shape');
    if (shape === 'dict') {
      var d = {};
      box.querySelectorAll('input[data-key]').forEach(function (i) { if (i.value.trim()) d[i.getAttribute('data-key')] = i.value.trim(); });
      return Object.keys(d).length ? d : null;
    }
    if (shape === 'list') {
      var lines = box.querySelector('textarea').value.split('\n').map(function (s) { return s.trim(); }).filter(Boolean);
      return lines.length ? lines : null;
    }
    var v = box.querySelector('input').value.trim();
    return v ? v : null;
  }
  function show(box) {
    var out = box.querySelector('[data-preview]'), v = value(box), part = box.getAttribute('data-field');
    if (v === null) { out.textContent = ''; out.className = 'preview'; return; }
    fetch('/api/v1/problems/' + encodeURIComponent(pid) + '/preview', {
      method: 'POST', credentials: 'same-origin',
      headers: {'Content-Type': 'application/json', 'X-CSRF-Token': csrf},
      body: JSON.stringify({part: part, value: v})
    }).then(function (r) { return r.json(); }).then(function (j) {
      if (j.error || j.detail) { out.className = 'preview error'; out.textContent = j.error || j.detail; }
      else if (j.mathml) { out.className = 'preview'; out.innerHTML = 'read as ' + j.mathml; }
      else { out.className = 'preview'; out.textContent = 'read as ' + j.text; }
      out.setAttribute('data-ready', 'yes');
      reachable();
    }).catch(function () { out.className = 'preview error'; out.textContent = 'no preview (the server did not answer)'; });
  }
  function reachable() {
    document.querySelectorAll('.readas, .preview, pre').forEach(function (e) {
      var scrolls = e.scrollWidth > e.clientWidth || e.scrollHeight > e.clientHeight;
      if (scrolls) e.setAttribute('tabindex', '0'); else e.removeAttribute('tabindex');
    });
  }
  reachable();
  window.addEventListener('resize', reachable);
  document.querySelectorAll('[data-field]').forEach(function (box) {
    box.addEventListener('input', function () {
      var k = box.getAttribute('data-field');
      clearTimeout(timers[k]);
      timers[k] = setTimeout(function () { show(box); }, 250);
    });
    if (value(box) !== null) show(box);
  });
  // after a check the page comes back with its result (or the reason it has none) far below the
  // top: focus goes to it (its heading is read out), and the status region says it in one line
  var fresh = document.querySelector('[data-fresh]');
  if (fresh) {
    fresh.focus();
    fresh.scrollIntoView({block: 'start'});
    var say = document.getElementById('announce');
    if (say) {
      var words = fresh.getAttribute('data-announce') || fresh.textContent;
      setTimeout(function () { say.textContent = words.replace(/\s+/g, ' ').trim(); }, 100);
    }
    document.body.setAttribute('data-focused', fresh.id || 'yes');
  }
})();
