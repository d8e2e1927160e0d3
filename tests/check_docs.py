#!/usr/bin/env python3
"""The user's documentation is whole and true to the program: every scene key the reader
accepts is in docs/scene-file.md under its section as the reader's key table prints it (its
default, what it expects, what it means), every option the commands' --help names
and every top-level JSON key `simulate --json` prints is in docs/commands.md, every link
between the docs resolves, and nothing a user reads sends them to files a clone lacks.

usage: check_docs.py ZIPOPT_EXE SOURCE_DIR SCENE_KEYS_MD_EXE"""
import json
import os
import re
import subprocess
import sys
import tempfile

from checklib import check, done

exe, src, keys_exe = sys.argv[1], sys.argv[2], sys.argv[3]


def read(rel):
    with open(os.path.join(src, rel), encoding="utf-8") as f:
        return f.read()


# the key tables: under each `## [section]` heading the first table is the one the reader's key
# table (src/io/scene_keys.def) prints
def key_tables(text):
    """{section: the lines of the first table under its `## [section]` heading}"""
    out = {}
    for sec, block in re.findall(r"^## \[([a-z]+)\]\n(.*?)(?=^## |\Z)", text, re.S | re.M):
        lines = block.split("\n")
        first = next((i for i, line in enumerate(lines) if line.startswith("|")), len(lines))
        end = first
        while end < len(lines) and lines[end].startswith("|"):
            end += 1
        out[sec] = lines[first:end]
    return out


printed = subprocess.run([keys_exe], capture_output=True, text=True, check=True).stdout
wanted = key_tables(printed)
if len(wanted) < 10 or sum(len(t) - 2 for t in wanted.values()) < 40:
    check(False, "%s printed no key tables" % keys_exe)
documented = key_tables(read("docs/scene-file.md"))
for sec, table in wanted.items():
    if sec not in documented:
        check(False, "docs/scene-file.md has no heading `## [%s]`" % sec)
    elif documented[sec] != table:
        check(False, "docs/scene-file.md: the table of [%s] is not the one the reader's key "
              "table prints (%s); it should be:\n%s" % (sec, keys_exe, "\n".join(table)))

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
