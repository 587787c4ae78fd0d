#!/usr/bin/env bash
# The user guide builds into a site with MkDocs in strict mode (a link to a page that does not
# exist fails the build) and every link and anchor in the built site resolves
# (tests/docs/check_site.py). Then the checker is shown to fail on a broken link and a broken
# anchor, so that this test can fail.
# usage: site.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
command -v mkdocs >/dev/null || { echo "mkdocs is not installed (scripts/setup.sh installs Debian's mkdocs)"; exit 1; }
mkdocs build --strict --quiet --config-file "$source_dir/mkdocs.yml" --site-dir "$work/site"
python3 "$source_dir/tests/docs/check_site.py" "$work/site"

# The checker must see a missing page and a missing anchor.
cp -r "$work/site" "$work/broken"
page="$work/broken/guide/inputs.html"
grep -q '</body>' "$page"
sed -i 's#</body>#<a href="no-such-page.html">x</a><a href="solve.html\#no-such-anchor">y</a></body>#' "$page"
if python3 "$source_dir/tests/docs/check_site.py" "$work/broken" >"$work/broken.txt" 2>&1; then
  echo "check_site.py passed a site with broken links"; exit 1
fi
grep -q "guide/inputs.html: no-such-page.html: no such file" "$work/broken.txt"
grep -q "no id 'no-such-anchor' in guide/solve.html" "$work/broken.txt"
echo "docs site: built and every link resolves"
