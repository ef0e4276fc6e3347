// Injected into a rendered report by tests/report/html_test.sh: on window load, counts the images
// that did not load (naturalWidth 0), the lines of text outside code that are raw Markdown (starting
// with '|' or '#', or holding '![' or ']('), and the in-page links ("#id") whose target does not
// exist; writes them into a pre element of id html-check, which `chromium --headless --dump-dom` prints.
window.addEventListener('load', function () {
  var images = Array.prototype.slice.call(document.images);
  var broken = images.filter(function (i) { return i.naturalWidth === 0; })
                     .map(function (i) { return 'broken image: ' + i.getAttribute('src'); });
  var raw = [];
  var walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT, {
    acceptNode: function (n) {
      return n.parentElement.closest('pre, code, script, style') ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT;
    }
  });
  for (var n = walker.nextNode(); n; n = walker.nextNode())
    n.nodeValue.split('\n').forEach(function (line) {
      var l = line.replace(/^\s+/, '');
      if (/^[|#]/.test(l) || l.indexOf('![') >= 0 || l.indexOf('](') >= 0) raw.push('raw Markdown: ' + l.slice(0, 120));
    });
  var links = Array.prototype.slice.call(document.querySelectorAll('a[href^="#"]'));
  var dangling = links.filter(function (a) { return !document.getElementById(decodeURIComponent(a.getAttribute('href').slice(1))); })
                      .map(function (a) { return 'link to a missing heading: ' + a.getAttribute('href'); });
  var out = document.createElement('pre');
  out.id = 'html-check';
  out.textContent = ['images=' + images.length, 'broken=' + broken.length, 'raw=' + raw.length, 'dangling=' + dangling.length]
                      .join(' ') + '\n' + broken.concat(raw, dangling).join('\n');
  document.body.appendChild(out);
});
