"""The llvmpipe side of simpview's side-by-side benchmark.

Draws one page that simpview.bench.LlvmpipeExport wrote (NAME.bin: the
triangles and line segments simpview hands its rasterizers, grouped in
drawing order by how they are lit and by which of the two they are)
through Mesa's llvmpipe, headless (OSMesa, a 4.5 core context), with
simpview's lighting formula, fog (A2's depth cue is one) and depth test in
GLSL, per pixel; a group whose u[14] is 1 (A2's pages 1 and 2, which
simpview draws on the panel itself) with no depth test. Warm: the
triangles are uploaded and the shaders compiled first, and 3 s of redraws
(at least 20) run; then it prints "ready".

Then it takes turns with simpview, which started it: for each line "turn"
read from stdin, one redraw untimed and TIMED_IN_A_TURN timed (clear colour
and depth, one draw call per group, glFinish), their times printed on one
line, in ms. It returns at the end of stdin. The two sides never draw at the
same time, and their turns alternate over the whole run, so both see the
host's cores as they are then (on this machine the same two-thread picture
takes 20-25 % longer for a second or so at a time, see docs/performance-log.md,
session 17).

Usage: python draw.py DIR NAME   (with SIMPVIEW_LLVMPIPE_PNG=1 also writes
DIR/NAME-llvmpipe.png at the end, the panel as llvmpipe drew it, to look at
beside simpview's)
"""
import os
import struct
import sys
import time
import zlib

os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")

import numpy as np  # noqa: E402
from OpenGL import GL, arrays, osmesa  # noqa: E402

SIZE = 650
UNIFORMS = 80
FLOATS = 13
TIMED_IN_A_TURN = 20

VERTEX = """
#version 330 core
layout(location = 0) in vec4 clip;
layout(location = 1) in vec4 zrgb;
layout(location = 2) in vec4 pn;
layout(location = 3) in float nz;
out vec4 v_zrgb;
out vec4 v_pn;
out float v_nz;
void main() {
    gl_Position = clip;
    v_zrgb = zrgb;
    v_pn = pn;
    v_nz = nz;
}
"""

# SPEC's lighting: I = kd Ia + sum_i (Ii fi) (kd (N.Li) + ks max(0, V.Ri)^p),
# fi = 1 / (A + B d), clamped to [0, 1]; then fog on camera-space z.
FRAGMENT = """
#version 330 core
in vec4 v_zrgb;
in vec4 v_pn;
in float v_nz;
out vec4 colour;
uniform float u[80];
void main() {
    vec3 c = v_zrgb.yzw;
    float z = v_zrgb.x;
    if (u[0] > 0.5) {
        vec3 kd = c;
        vec3 P = vec3(v_pn.x, v_pn.y, z);
        vec3 N = vec3(v_pn.z, v_pn.w, v_nz);
        float nl = length(N);
        N = nl > 0.0 ? N / nl : N;
        vec3 V = u[12] > 0.5 ? normalize(-P) : vec3(0.0, 0.0, 1.0);
        c = kd * vec3(u[7], u[8], u[9]);
        int lights = int(u[13]);
        for (int i = 0; i < lights; i++) {
            int o = 16 + 8 * i;
            vec3 toLight = vec3(u[o], u[o + 1], u[o + 2]) - P;
            float d = length(toLight);
            vec3 L = toLight / d;
            float nDotL = dot(N, L);
            if (nDotL > 0.0) {
                vec3 R = 2.0 * nDotL * N - L;
                float f = 1.0 / (u[o + 6] + u[o + 7] * d);
                float spec = u[10] * pow(max(0.0, min(1.0, dot(V, R))), u[11]);
                c += vec3(u[o + 3], u[o + 4], u[o + 5]) * f * (kd * nDotL + spec);
            }
        }
        c = clamp(c, 0.0, 1.0);
    }
    if (u[1] > 0.5 && z < u[2]) {
        float t = clamp((z - u[3]) / (u[2] - u[3]), 0.0, 1.0);
        c = t * c + (1.0 - t) * vec3(u[4], u[5], u[6]);
    }
    colour = vec4(c, 1.0);
}
"""


def context():
    attrs = arrays.GLintArray.asArray([
        osmesa.OSMESA_FORMAT, osmesa.OSMESA_RGBA, osmesa.OSMESA_DEPTH_BITS, 24,
        osmesa.OSMESA_PROFILE, osmesa.OSMESA_CORE_PROFILE,
        osmesa.OSMESA_CONTEXT_MAJOR_VERSION, 4, osmesa.OSMESA_CONTEXT_MINOR_VERSION, 5, 0])
    ctx = osmesa.OSMesaCreateContextAttribs(attrs, None)
    buf = arrays.GLubyteArray.zeros((SIZE, SIZE, 4))
    if not osmesa.OSMesaMakeCurrent(ctx, buf, GL.GL_UNSIGNED_BYTE, SIZE, SIZE):
        raise SystemExit("OSMesa: no context")
    return ctx, buf


def program():
    def shader(kind, source):
        s = GL.glCreateShader(kind)
        GL.glShaderSource(s, source)
        GL.glCompileShader(s)
        if not GL.glGetShaderiv(s, GL.GL_COMPILE_STATUS):
            raise SystemExit(GL.glGetShaderInfoLog(s).decode())
        return s
    p = GL.glCreateProgram()
    GL.glAttachShader(p, shader(GL.GL_VERTEX_SHADER, VERTEX))
    GL.glAttachShader(p, shader(GL.GL_FRAGMENT_SHADER, FRAGMENT))
    GL.glLinkProgram(p)
    if not GL.glGetProgramiv(p, GL.GL_LINK_STATUS):
        raise SystemExit(GL.glGetProgramInfoLog(p).decode())
    return p


def load(path):
    raw = open(path, "rb").read()
    at = 0
    groups = int(np.frombuffer(raw, "<i4", 1, at)[0])
    at += 4
    uniforms, modes, counts, vertices = [], [], [], []
    for _ in range(groups):
        uniforms.append(np.frombuffer(raw, "<f4", UNIFORMS, at).copy())
        at += 4 * UNIFORMS
        modes.append(GL.GL_LINES if int(np.frombuffer(raw, "<i4", 1, at)[0]) == 1 else GL.GL_TRIANGLES)
        at += 4
        n = int(np.frombuffer(raw, "<i4", 1, at)[0])
        at += 4
        vertices.append(np.frombuffer(raw, "<f4", n * FLOATS, at))
        at += 4 * n * FLOATS
        counts.append(n)
    return uniforms, modes, counts, np.concatenate(vertices) if vertices else np.zeros(0, "<f4")


def write_png(path, rgba):
    """The SIZE x SIZE RGBA buffer (bottom row first, as OpenGL reads it) as an RGB PNG."""
    rows = rgba[::-1, :, :3]
    raw = b"".join(b"\x00" + rows[y].tobytes() for y in range(rows.shape[0]))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    header = struct.pack(">IIBBBBB", rows.shape[1], rows.shape[0], 8, 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def main():
    folder, name = sys.argv[1], sys.argv[2]
    ctx, buf = context()
    prog = program()
    GL.glUseProgram(prog)
    where = GL.glGetUniformLocation(prog, "u")
    GL.glViewport(0, 0, SIZE, SIZE)
    GL.glEnable(GL.GL_DEPTH_TEST)
    GL.glClearColor(0, 0, 0, 1)
    uniforms, modes, counts, data = load(os.path.join(folder, name + ".bin"))
    vao = GL.glGenVertexArrays(1)
    GL.glBindVertexArray(vao)
    vbo = GL.glGenBuffers(1)
    GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo)
    GL.glBufferData(GL.GL_ARRAY_BUFFER, data.nbytes, data, GL.GL_STATIC_DRAW)
    stride = 4 * FLOATS
    for index, (size, offset) in enumerate([(4, 0), (4, 16), (4, 32), (1, 48)]):
        GL.glEnableVertexAttribArray(index)
        GL.glVertexAttribPointer(index, size, GL.GL_FLOAT, GL.GL_FALSE, stride, GL.GLvoidp(offset))
    firsts = np.cumsum([0] + counts[:-1]).tolist()
    # Strictly nearer wins, as simpview's z-buffer; or every fragment, in drawing order.
    tests = [GL.GL_ALWAYS if u[14] > 0.5 else GL.GL_LESS for u in uniforms]
    depth_test = [None]  # the one in force: set only where it changes, so a page of one costs no call a redraw

    def redraw():
        GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
        for u, test, mode, first, count in zip(uniforms, tests, modes, firsts, counts):
            if test != depth_test[0]:
                GL.glDepthFunc(test)
                depth_test[0] = test
            GL.glUniform1fv(where, UNIFORMS, u)
            GL.glDrawArrays(mode, first, count)
        GL.glFinish()

    # Warmed by 3 s of redraws, at least 20: llvmpipe compiles its shaders at
    # the first draw. (LlvmpipeExport warms simpview longer, for C2.)
    warm_until = time.perf_counter() + 3
    warmed = 0
    while warmed < 20 or time.perf_counter() < warm_until:
        redraw()
        warmed += 1
    print("ready", flush=True)
    for line in sys.stdin:
        if line.strip() != "turn":
            raise SystemExit("draw.py: expected a line 'turn', got " + repr(line))
        redraw()  # untimed: the cores may still be simpview's for a moment
        times = []
        for _ in range(TIMED_IN_A_TURN):
            start = time.perf_counter()
            redraw()
            times.append((time.perf_counter() - start) * 1000)
        print(" ".join("%.4f" % t for t in times), flush=True)
    if os.environ.get("SIMPVIEW_LLVMPIPE_PNG"):
        pixels = GL.glReadPixels(0, 0, SIZE, SIZE, GL.GL_RGBA, GL.GL_UNSIGNED_BYTE)
        write_png(os.path.join(folder, name + "-llvmpipe.png"),
                  np.frombuffer(pixels, np.uint8).reshape(SIZE, SIZE, 4))
    GL.glDeleteBuffers(1, [vbo])
    GL.glDeleteVertexArrays(1, [vao])
    osmesa.OSMesaDestroyContext(ctx)


if __name__ == "__main__":
    main()
