#!/bin/sh
# Installs what the llvmpipe side of the benchmark needs, for this benchmark
# only (neither the build nor the tests use it): Mesa's OSMesa (llvmpipe)
# from Debian, and PyOpenGL and numpy from PyPI into build/llvmpipe-venv.
set -e
here=$(cd "$(dirname "$0")" && pwd)
venv="$here/../../build/llvmpipe-venv"
if ! ldconfig -p | grep -q libOSMesa.so; then
    apt-get install -y libosmesa6 || { apt-get update && apt-get install -y libosmesa6; }
fi
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
fi
"$venv/bin/pip" install -q PyOpenGL numpy
