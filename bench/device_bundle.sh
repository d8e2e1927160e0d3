#!/usr/bin/env bash
# A self-contained copy of the build for a machine that cannot install packages (a lent
# many-core machine, a cluster node without Debian's libraries): the binaries, every shared
# library they load, the loader, OpenMPI's launcher with its plugins, and the compiled courses
# of the scenes in config/ (so the machine needs no compiler). bench/device_scaling.sh runs the
# scaling benchmarks from it.
#   usage: bench/device_bundle.sh [DIR]   (default out/device; build/ must be built first)
# On the other machine, from the repository root: `. DIR/env.sh` sets PATH, LD_LIBRARY_PATH,
# OPAL_PREFIX and XDG_CACHE_HOME; the binaries then run as usual (mpirun included).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-out/device}
rm -rf "$dir"
mkdir -p "$dir/bin" "$dir/lib" "$dir/sys" "$dir/cache"

# the C library and the loader go apart (sys/): they are used only through the loader
# (sys/run), never by LD_LIBRARY_PATH, so the other machine's own programs keep their libc
copy_libs() {
  ldd "$@" 2>/dev/null | awk '/=> \// { print $3 } /ld-linux/ && !/=>/ { print $1 }' |
    sort -u | while read -r lib; do
      case $(basename "$lib") in
      libc.so.* | libm.so.* | libpthread.so.* | libdl.so.* | librt.so.* | ld-linux*) dest=sys ;;
      *) dest=lib ;;
      esac
      [ -e "$dir/$dest/$(basename "$lib")" ] || cp -L "$lib" "$dir/$dest/"
    done
}

for exe in zipopt bench_sim search_budget brute_force; do
  [ -x "build/$exe" ] && cp "build/$exe" "$dir/bin/"
done
copy_libs "$dir"/bin/*

# OpenMPI as an installation tree of its own, relocated by OPAL_PREFIX
if command -v orterun >/dev/null; then
  pkglib=$(ompi_info --path pkglibdir --parsable | sed 's/.*://')
  libdir=$(ompi_info --path libdir --parsable | sed 's/.*://')
  prefix=$(ompi_info --path prefix --parsable | sed 's/.*://')
  datadir=$(ompi_info --path pkgdatadir --parsable | sed 's/.*://')
  mpi=$dir/mpi
  mkdir -p "$mpi$prefix/bin" "$mpi$pkglib" "$mpi$datadir" "$mpi$libdir"
  cp -L "$(command -v orterun)" "$(command -v orted)" "$mpi$prefix/bin/"
  ln -s orterun "$mpi$prefix/bin/mpirun"
  cp -L "$pkglib"/*.so "$mpi$pkglib/"
  cp -rL "$datadir"/. "$mpi$datadir/"
  copy_libs "$mpi$prefix"/bin/* "$mpi$pkglib"/*.so
  echo "$prefix" >"$dir/mpi_prefix"
fi

# the compiled courses of every scene, made here where the compiler is
for scene in config/*.ini; do
  XDG_CACHE_HOME=$PWD/$dir/cache build/zipopt simulate "$scene" --out "$dir/tmp" >/dev/null
done

rm -rf "$dir/tmp"
cat >"$dir/sys/run" <<'EOF'
#!/bin/sh
# runs a bundled binary through the bundled loader and C library
here=$(cd "$(dirname "$0")/.." && pwd)
exec "$here/sys/ld-linux-x86-64.so.2" --library-path "$here/lib:$here/sys" "$@"
EOF
chmod +x "$dir/sys/run"
cat >"$dir/env.sh" <<'EOF'
# sourced: the bundle's binaries, libraries, MPI and compiled courses
b=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
export PATH="$b/bin:$PATH" LD_LIBRARY_PATH="$b/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export XDG_CACHE_HOME="$b/cache"
if [ -f "$b/mpi_prefix" ]; then
  export OPAL_PREFIX="$b/mpi$(cat "$b/mpi_prefix")" PATH="$b/mpi$(cat "$b/mpi_prefix")/bin:$PATH"
fi
EOF
du -sh "$dir"
