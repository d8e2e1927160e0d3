#!/usr/bin/env python3
"""report.html is one self-contained page: a real headless browser (Debian's chromium) loads the
search's report.html offline and finds every figure report.md shows decoded and drawn, and no
resource fetched from anywhere but the page itself; the page has report.md's tables.

usage: check_report_html.py ZIPOPT_EXE SOURCE_DIR"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]
browser = shutil.which("chromium") or shutil.which("chromium-browser")
if not browser:
    print("FAIL: no chromium: apt-get install chromium (the report's browser check needs it)")
    sys.exit(1)

# the page loads report.html beside it and writes what it found into its own body
HARNESS = """<!DOCTYPE html><html><body><iframe id="r" src="report.html"></iframe><script>
document.getElementById('r').onload = function () {
  var d = this.contentDocument, w = this.contentWindow, bad = [];
  var imgs = d.images;
  for (var i = 0; i < imgs.length; i++) {
    if (!imgs[i].complete || imgs[i].naturalWidth === 0) bad.push('undrawn image ' + i);
    if (imgs[i].src.indexOf('data:image/') !== 0) bad.push('image from ' + imgs[i].src);
  }
  w.performance.getEntriesByType('resource').forEach(function (e) {
    if (e.name.indexOf('data:') !== 0) bad.push('fetched ' + e.name);
  });
  ['link', 'script', 'iframe', 'object', 'embed'].forEach(function (t) {
    if (d.getElementsByTagName(t).length) bad.push('a <' + t + '> element');
  });
  document.body.setAttribute('data-result', 'images=' + imgs.length + ' tables=' +
      d.getElementsByTagName('table').length + ' bad=' + (bad.join('; ') || 'none'));
};
</script></body></html>
"""

with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "search")
    p = subprocess.run([exe, os.path.join(src, "config", "seed.ini"), "--max-evals", "300",
                        "--out", out], capture_output=True, text=True)
    if p.returncode not in (0, 3):
        print("FAIL: the search: exit %d: %s" % (p.returncode, p.stderr[-600:]))
        sys.exit(1)
    with open(os.path.join(out, "report.md"), encoding="utf-8") as f:
        md = f.read()
    want_images = len(re.findall(r"!\[[^]]*\]\([^)]+\)", md))
    want_tables = len(re.findall(r"^\|[-| ]+\|$", md, re.M))  # a table's delimiter row
    with open(os.path.join(out, "check.html"), "w", encoding="utf-8") as f:
        f.write(HARNESS)
    profile = os.path.join(tmp, "profile")
    r = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu",
                        "--allow-file-access-from-files", "--user-data-dir=" + profile,
                        "--virtual-time-budget=20000", "--dump-dom",
                        "file://" + os.path.join(out, "check.html")],
                       capture_output=True, text=True, timeout=120)
    m = re.search(r'data-result="images=(\d+) tables=(\d+) bad=([^"]*)"', r.stdout)
    if not m:
        check(False, "the browser did not load report.html: %s" % r.stderr[-600:])
    else:
        images, tables, bad = int(m.group(1)), int(m.group(2)), m.group(3)
        if want_images < 4:
            check(False, "report.md shows %d figures; the search draws 4" % want_images)
        if images != want_images:
            check(False, "report.html shows %d images, report.md %d" % (images, want_images))
        if tables != want_tables or tables == 0:
            check(False, "report.html has %d tables, report.md %d" % (tables, want_tables))
        if bad != "none":
            check(False, "report.html: " + bad)
    # no file the page could need lies beside it: it is one file
    with open(os.path.join(out, "report.html"), encoding="utf-8") as f:
        page = f.read()
    if re.search(r'(src|href)="(?!data:|#|https?:)[^"]+"', page):
        check(False, "report.html refers to a file beside it")

done("check_report_html")
