#!/usr/bin/env bash
# The documentation's links (issue 37): every relative link and image in README.md and docs/*.md
# must resolve from the file that holds it, and an anchor (#section) must name a heading of the
# markdown file it points into, by GitHub's rule (lowercase; spaces to '-'; punctuation other than
# '-' and '_' dropped; a repeated heading gets -1, -2, ...). http(s), mailto and other schemes are
# not checked. README.md, the front door, may hold at most 300 lines.
# Usage: tests/docs_links_test.sh [REPOSITORY_ROOT]   (default: this script's folder's parent)
set -euo pipefail
root=${1:-$(cd "$(dirname "$0")/.." && pwd)}
[[ -f $root/README.md ]] || { echo "docs_links: $root/README.md not found" >&2; exit 1; }

exec python3 - "$root" <<'PYTHON'
import os, re, sys, urllib.parse

root = os.path.abspath(sys.argv[1])
MAX_README_LINES = 300

files = [os.path.join(root, 'README.md')]
for folder, _, names in sorted(os.walk(os.path.join(root, 'docs'))):
    files += [os.path.join(folder, n) for n in sorted(names) if n.endswith('.md')]

FENCE = re.compile(r'^ {0,3}(`{3,}|~{3,})')
HEADING = re.compile(r'^ {0,3}(#{1,6})(?:[ \t]+(.*?))?(?:[ \t]+#+)?[ \t]*$')
CODE_SPAN = re.compile(r'(`+)(?:(?!\1).)+?\1')
LINK = re.compile(r'!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*(<[^>]*>|[^\s)]+)(?:\s+(?:"[^"]*"|\'[^\']*\'|\([^)]*\)))?\s*\)')
REFERENCE = re.compile(r'^ {0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)')
HTML = re.compile(r'<(?:a|img)\b[^>]*?\b(?:href|src)\s*=\s*"([^"]*)"', re.IGNORECASE)
SCHEME = re.compile(r'^[A-Za-z][A-Za-z0-9+.-]*:')

def prose_lines(path):
    """(line number, text) of the lines outside fenced code blocks."""
    fence = None
    with open(path, encoding='utf-8') as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip('\n')
            m = FENCE.match(line)
            if fence is None and m:
                fence = m.group(1)
                continue
            if fence is not None:
                if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) \
                        and line.strip() == m.group(1):
                    fence = None
                continue
            yield number, line

def github_anchor(text):
    text = re.sub(r'!?\[([^\]]*)\]\([^)]*\)', r'\1', text)   # a link counts by its text
    text = re.sub(r'<[^>]+>', '', text)                       # HTML tags
    text = text.strip().lower()
    text = re.sub(r'[^\w\- ]', '', text)                      # punctuation, backticks, emphasis
    return text.replace(' ', '-')

anchor_cache = {}
def anchors(path):
    if path not in anchor_cache:
        seen, found = {}, set()
        for _, line in prose_lines(path):
            m = HEADING.match(line)
            if not m:
                continue
            base = github_anchor(m.group(2) or '')
            n = seen.get(base, 0)
            seen[base] = n + 1
            found.add(base if n == 0 else '%s-%d' % (base, n))
        anchor_cache[path] = found
    return anchor_cache[path]

broken, checked = [], 0
for path in files:
    rel = os.path.relpath(path, root)
    targets = []
    for _, line in prose_lines(path):
        m = REFERENCE.match(line)
        if m:
            targets.append(m.group(1))
        text = CODE_SPAN.sub('', line)   # a code span is not a link
        targets += LINK.findall(text)
        targets += HTML.findall(text)
    for target in targets:
        target = target.strip('<>')
        if SCHEME.match(target):
            continue
        checked += 1
        part, _, anchor = target.partition('#')
        part = urllib.parse.unquote(part)
        if part == '':
            resolved = path
        elif part.startswith('/'):
            resolved = os.path.join(root, part.lstrip('/'))
        else:
            resolved = os.path.normpath(os.path.join(os.path.dirname(path), part))
        ok = os.path.exists(resolved)
        if ok and anchor and resolved.endswith('.md') and os.path.isfile(resolved):
            ok = urllib.parse.unquote(anchor) in anchors(resolved)
        if not ok:
            broken.append('%s: broken link %s' % (rel, target))

with open(os.path.join(root, 'README.md'), encoding='utf-8') as f:
    readme_lines = sum(1 for _ in f)
if readme_lines > MAX_README_LINES:
    broken.append('README.md: %d lines, more than %d' % (readme_lines, MAX_README_LINES))

for line in broken:
    print(line)
if broken:
    print('docs_links: FAILED, %d problem(s) in %d files' % (len(broken), len(files)))
    sys.exit(1)
print('docs_links: %d relative links in %d files resolve; README.md has %d lines (at most %d)'
      % (checked, len(files), readme_lines, MAX_README_LINES))
PYTHON
