#!/usr/bin/env python3
"""The user's documentation is whole and true to the program: every scene key the reader
accepts is in docs/scene-file.md under its section, every option the commands' --help names
and every top-level JSON key `simulate --json` prints is in docs/commands.md, every link
between the docs resolves, and nothing a user reads sends them to files a clone lacks.

usage: check_docs.py ZIPOPT_EXE SOURCE_DIR"""
import json
import os
import re
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src = sys.argv[1], sys.argv[2]


def read(rel):
    with open(os.path.join(src, rel), encoding="utf-8") as f:
        return f.read()


# the reader's key table: `[K_ID] = {S_SECTION, "name", ...}` and the section names in order
lines_c = read("src/io/scene_lines.c")
sec_names = re.search(r"zp_scene_sec_names\[S_COUNT\] = \{(.*?)\};", lines_c, re.S).group(1)
sections = re.findall(r'"([a-z]+)"', sec_names)
keys = re.findall(r'\[K_[A-Z0-9_]+\] = \{S_([A-Z]+), "([a-z0-9_]+)"', lines_c)
if len(keys) < 40 or not sections:
    check(False, "could not read the key table of src/io/scene_lines.c (%d keys)" % len(keys))

scene_doc = read("docs/scene-file.md")
# the text under each `## [section]` heading
blocks = dict(re.findall(r"^## \[([a-z]+)\]\n(.*?)(?=^## |\Z)", scene_doc, re.S | re.M))
for s in sections:
    if s not in blocks:
        check(False, "docs/scene-file.md has no heading `## [%s]`" % s)
for sec, name in keys:
    block = blocks.get(sec.lower(), "")
    if not re.search(r"^\| `%s` \|" % re.escape(name), block, re.M):
        check(False, "docs/scene-file.md does not document [%s] %s in a table row" % (sec.lower(), name))

# every option of every command's --help
commands_doc = read("docs/commands.md")
help_all = subprocess.run([exe, "--help-all"], capture_output=True, text=True, check=True).stdout
for opt in sorted(set(re.findall(r"(?<![\w-])--[a-z][a-z-]*", help_all))):
    if not re.search(r"`[^`]*%s(?![a-z-])" % re.escape(opt), commands_doc):
        check(False, "docs/commands.md does not document the option %s" % opt)

# every top-level key of simulate --json, on a plain scene and one with every optional effect
for scene in ("config/seed.ini", "config/seed_real.ini"):
    with tempfile.TemporaryDirectory() as tmp:
        out = subprocess.run([exe, "simulate", os.path.join(src, scene), "--json",
                              "--sample-times", "1", "--out", tmp],
                             capture_output=True, text=True)
    try:
        obj = json.loads(out.stdout)
    except ValueError:
        check(False, "simulate %s --json printed no JSON object: %s" % (scene, out.stderr.strip()))
        continue
    for key in obj:
        if "`%s`" % key not in commands_doc:
            check(False, "docs/commands.md does not document the JSON key %s (simulate %s)" % (key, scene))

# links between the docs resolve (files, and anchors as headings render them)
def anchors(text):
    out = set()
    for h in re.findall(r"^#+ (.*)$", text, re.M):
        slug = re.sub(r"[^\w\- ]", "", h.strip().lower()).replace(" ", "-")
        out.add(slug)
    return out


docs = ["README.md"] + ["docs/" + f for f in sorted(os.listdir(os.path.join(src, "docs")))
                        if f.endswith(".md")]
for doc in docs:
    text = read(doc)
    for target in re.findall(r"\]\(([^)\s]+)\)", text):
        if re.match(r"[a-z]+:", target):
            continue
        path, _, anchor = target.partition("#")
        full = os.path.normpath(os.path.join(src, os.path.dirname(doc), path)) if path else \
            os.path.join(src, doc)
        if not os.path.exists(full):
            check(False, "%s links to %s, which does not exist" % (doc, target))
        elif anchor and full.endswith(".md"):
            with open(full, encoding="utf-8") as f:
                if anchor not in anchors(f.read()):
                    check(False, "%s links to %s: no such heading" % (doc, target))

# nothing a user reads points outside the clone
outside = re.compile(r"\.\./shared|\b(CONFIG|CLI|MODEL)\.md")
readable = {d: read(d) for d in docs}
readable["man/zipopt.h2m"] = read("man/zipopt.h2m")
readable["zipopt --help-all"] = help_all
for name, text in readable.items():
    m = outside.search(text)
    if m:
        check(False, "%s refers to %s, which a user's clone does not have" % (name, m.group(0)))

readme_lines = read("README.md").count("\n")
if readme_lines > 300:
    check(False, "README.md has %d lines; it is the front door (at most 300), details go to docs/"
         % readme_lines)

done("check_docs")
