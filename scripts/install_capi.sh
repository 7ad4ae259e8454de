#!/usr/bin/env bash
# Install Thinwall's C ABI for C hosts: the libraries, the header and a
# pkg-config file under a prefix. A host built with
#   cc host.c $(pkg-config --cflags --libs thinwall)
# (PKG_CONFIG_PATH=PREFIX/lib/pkgconfig for a prefix pkg-config does not
# search) runs without LD_LIBRARY_PATH: the .pc file adds an rpath.
#
#   scripts/install_capi.sh [--prefix DIR] [--from BUILD_DIR]
#
# --prefix: where to install (default /usr/local).
# --from:   a directory holding libthinwall.so and libthinwall.a already built
#           (default: `cargo build --release -p thinwall-clib`, then target/release).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
prefix=/usr/local
from=""
while [ $# -gt 0 ]; do
  case "$1" in
    --prefix) prefix="$2"; shift 2 ;;
    --from) from="$2"; shift 2 ;;
    *) echo "install_capi.sh: unknown argument '$1' (see the script's head)" >&2; exit 2 ;;
  esac
done
if [ -z "$from" ]; then
  (cd "$root" && cargo build --release -p thinwall-clib)
  from="$root/target/release"
fi
for f in libthinwall.so libthinwall.a; do
  [ -f "$from/$f" ] || { echo "install_capi.sh: $from/$f not found" >&2; exit 1; }
done
mkdir -p "$prefix/lib/pkgconfig" "$prefix/include"
install -m 0755 "$from/libthinwall.so" "$prefix/lib/libthinwall.so"
install -m 0644 "$from/libthinwall.a" "$prefix/lib/libthinwall.a"
install -m 0644 "$root/plugin-api/include/thinwall.h" "$prefix/include/thinwall.h"
sed "s|^prefix=.*|prefix=$prefix|" "$root/plugin-api/thinwall.pc" > "$prefix/lib/pkgconfig/thinwall.pc"
echo "installed libthinwall, thinwall.h and thinwall.pc under $prefix"
