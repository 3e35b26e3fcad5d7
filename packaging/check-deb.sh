#!/usr/bin/env bash
# Builds the Debian package from the binaries `cargo test --workspace` has just built (the dev
# profile: no release build here), unpacks it into a scratch root and checks what a user gets:
# the installed binary's --version, `solve` on one line and `render` of the default diagram run
# from a folder outside the repository, the .desktop entry passes desktop-file-validate and
# names an installed command and icon, every man page renders with `man -l`, and the bash
# completion parses. Run by .ci/run after the tests; needs desktop-file-utils and man-db.
#
# The package a user installs is built the same way but optimised: see docs/install.md.
set -euo pipefail
cd "$(dirname "$0")/.."
started=$SECONDS
target="${CARGO_TARGET_DIR:-target}"
# cargo-deb, pinned: it warns that the dev profile "will be a hard error in the future", so a
# newer release may refuse what this script asks of it. Built unoptimised (--debug): that
# takes half the time (36 s against 71 s here) and packs this package as fast (4 s).
cargo_deb_version=3.8.0
if [ "$(cargo deb --version 2>/dev/null || true)" != "cargo-deb $cargo_deb_version" ]; then
  cargo install cargo-deb --version "$cargo_deb_version" --locked --debug
fi
# Built by `cargo test --workspace` with the test run's features: `cargo xtask` (cargo run)
# would build the program's dependencies again with its own.
for built in "$target/debug/xtask" "$target/debug/refraction-explorer"; do
  if [ ! -x "$built" ]; then
    echo "check-deb: no $built: run cargo test --workspace first" >&2
    exit 1
  fi
done
"$target/debug/xtask" dist-assets
rm -rf "$target/debian"
# --fast: xz at its quickest, which is enough for a check (the package a user installs is
# built with the default compression).
deb=$(cargo deb --profile dev --no-build --fast --quiet | tail -n 1)
echo "check-deb: built $deb ($(du -k "$deb" | cut -f1) KiB)"

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
root="$scratch/root"
dpkg-deb -x "$deb" "$root"
bin="$root/usr/bin/refraction-explorer"

fail() {
  echo "check-deb: $*" >&2
  exit 1
}

version=$(grep -m1 '^version = ' Cargo.toml | cut -d'"' -f2)
[ "$("$bin" --version)" = "refraction-explorer $version" ] || fail "--version: $("$bin" --version)"
[ "$(dpkg-deb -f "$deb" Version)" = "$version-1" ] || fail "the package's version"
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libgl1 libegl1 libxkbcommon-x11-0 libwayland-client0; do
  [[ ", $depends," == *", $lib"[,\ ]* ]] || fail "Depends lacks $lib: $depends"
done

# Outside the repository, with nothing but the installed binary: everything is compiled in.
work="$scratch/work"
mkdir "$work"
answer=$(cd "$work" && echo '{"w":[0.6,-0.8,0],"n":[0,1,0],"mu_i":1,"mu_t":1.5}' | "$bin" solve)
# W at 36.87° from air into glass: T = (0.4, -0.9165), sin θt = 0.6/1.5.
[[ "$answer" == '{"t":[0.39999999999999997,-0.9165151389911681,0.0],"tir":false,'* ]] ||
  fail "solve answered: $answer"
(cd "$work" && "$bin" render --out diagram.png)
[ "$(head -c 8 "$work/diagram.png" | od -An -tx1 | tr -d ' ')" = "89504e470d0a1a0a" ] ||
  fail "render --out diagram.png wrote no PNG"
(cd "$work" && "$bin" trace --list | grep '^droplet ' >/dev/null) || fail "trace --list lacks droplet"

desktop="$root/usr/share/applications/refraction-explorer.desktop"
desktop-file-validate "$desktop"
exec_line=$(grep -m1 '^Exec=' "$desktop" | cut -d= -f2-)
[ -x "$root/usr/bin/${exec_line%% *}" ] || fail "Exec=$exec_line is not an installed command"
icon=$(grep -m1 '^Icon=' "$desktop" | cut -d= -f2-)
[ -f "$root/usr/share/icons/hicolor/scalable/apps/$icon.svg" ] || fail "no scalable icon $icon"
[ -f "$root/usr/share/icons/hicolor/48x48/apps/$icon.png" ] || fail "no 48x48 icon $icon"

pages=0
for page in "$root"/usr/share/man/man1/*.1.gz; do
  name=$(basename "$page" .1.gz)
  rendered=$(MANWIDTH=80 man -l -P cat "$page" 2>"$scratch/man.err") || fail "man -l $name failed"
  [ ! -s "$scratch/man.err" ] || fail "man -l $name warned: $(cat "$scratch/man.err")"
  [[ "$rendered" == *NAME*"$name"*SYNOPSIS* ]] || fail "man -l $name: no NAME or SYNOPSIS"
  pages=$((pages + 1))
done
[ "$pages" = 7 ] || fail "$pages man pages, not 7 (the program and its six commands)"

bash -n "$root/usr/share/bash-completion/completions/refraction-explorer"
[ -s "$root/usr/share/zsh/vendor-completions/_refraction-explorer" ] || fail "no zsh completion"
[ -s "$root/usr/share/fish/vendor_completions.d/refraction-explorer.fish" ] ||
  fail "no fish completion"

echo "check-deb: the package checks out ($pages man pages) in $((SECONDS - started)) s."
