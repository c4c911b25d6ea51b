"""Draws one frame of the scene with OpenGL 3.3 (core profile), from the arrays of _yade._displayFrame():
no Python loop over bodies or contacts, one draw call per kind of thing. Each body is drawn by the drawer of
the drawing functor its shape's class chose (_SHAPE_DRAWERS, at the end: Gl1_Sphere, Gl1_Facet, Gl1_Box,
Gl1_Wall); a shape class no functor draws is reported once by name.

- spheres: one screen-facing square per sphere (instanced, front to back), in which the fragment shader
  intersects the view ray with the sphere and shades the hit point: a round, lit sphere of any size for two
  triangles (Gl1_Sphere.wire: a circle outline instead; Gl1_Sphere.stripes: sectors that turn with the
  sphere). Its depth is that of its front point, so a sphere
  cut by a facet, or two spheres overlapping by much, show the nearer one whole;
- facets and boxes: lit triangles (wire: their edges);
- walls: a grid of Gl1_Wall.div lines; bounds, the periodic cell, every pair (intrAllWire): lines;
- force chains (OpenGLRenderer.intrPhys, Gl1_NormPhys): a band between the two centres, facing the viewer,
  its width ∝ |normal force| (maxRadius at maxFn).
Colors are the shapes' colors; OpenGLRenderer says what is drawn (shape, bound, intrPhys, intrAllWire,
wire, mask), the lights and the background.
"""
import ctypes

import numpy
from OpenGL import GL

from yade import wrapper



def drawnBy(frame, functor):
    """Which bodies of the frame the drawing functor `functor` (a Gl1_* class name) draws (a boolean mask)."""
    names = list(frame['drawers'])
    if functor not in names:
        return numpy.zeros(len(frame['drawer']), bool)
    return frame['drawer'] == names.index(functor)


_warned = set()


def _warnOnce(message):
    if message not in _warned:
        _warned.add(message)
        import warnings
        warnings.warn(message, RuntimeWarning)

_LIGHTING = """
uniform vec3 lightDir1, lightDir2, lightColor1, lightColor2;
uniform float light1On, light2On;
vec3 shade(vec3 color, vec3 n, vec3 toEye) {
    vec3 c = color * (0.25 + 0.45 * max(dot(n, toEye), 0.0));  // ambient and a light at the eye
    vec3 d1 = normalize(lightDir1), d2 = normalize(lightDir2);
    c += light1On * color * lightColor1 * 0.6 * max(dot(n, d1), 0.0);
    c += light2On * color * lightColor2 * 0.6 * max(dot(n, d2), 0.0);
    c += light1On * 0.25 * pow(max(dot(reflect(-d1, n), toEye), 0.0), 24.0);
    return min(c, vec3(1.0));
}
"""

_SPHERE_VS = """#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec3 center;
layout(location = 2) in float radius;
layout(location = 3) in vec3 color;
layout(location = 4) in vec3 axis0;
layout(location = 5) in vec3 axis1;
layout(location = 6) in vec3 axis2;
uniform mat4 view, proj; uniform float ortho;
out vec3 vCenter; out float vRadius; out vec3 vColor; out vec3 vPos; flat out mat3 vToBody;
void main() {
    vec4 c = view * vec4(center, 1.0);
    vCenter = c.xyz; vRadius = radius; vColor = color;
    vToBody = transpose(mat3(view) * mat3(axis0, axis1, axis2));  // view → the body's own axes (stripes)
    // a square facing the eye at the sphere's front, just large enough to hold its outline (in perspective a
    // sphere looks wider than its radius: by d/sqrt(d²-r²) at distance d, plus a margin off the axis); drawn
    // front to back, hidden spheres fail the depth test before their pixels are shaded
    float d = length(c.xyz);
    float grow = ortho > 0.5 ? 1.0 : 1.15 / sqrt(max(1.0 - (radius * radius) / (d * d), 0.01));
    vec3 front = c.xyz + (ortho > 0.5 ? vec3(0.0, 0.0, radius) : -normalize(c.xyz) * radius * 0.999);
    vec3 p = vec3(front.xy + corner * radius * grow * (ortho > 0.5 ? 1.0 : max(-front.z, 1e-9) / max(-c.z, 1e-9)), front.z);
    vPos = p;
    gl_Position = proj * vec4(p, 1.0);
}
"""

_SPHERE_FS = """#version 330 core
in vec3 vCenter; in float vRadius; in vec3 vColor; in vec3 vPos; flat in mat3 vToBody;
uniform mat4 proj; uniform float ortho; uniform float wire; uniform float stripes;
out vec4 fragColor;
""" + _LIGHTING + """
void main() {
    vec3 origin = ortho > 0.5 ? vec3(vPos.xy, 0.0) : vec3(0.0);
    vec3 dir = ortho > 0.5 ? vec3(0.0, 0.0, -1.0) : normalize(vPos);
    vec3 oc = origin - vCenter;
    float b = dot(oc, dir), c = dot(oc, oc) - vRadius * vRadius;
    float disc = b * b - c;
    if (disc < 0.0) discard;
    float t = -b - sqrt(disc);
    vec3 hit = origin + t * dir;
    vec3 n = (hit - vCenter) / vRadius;
    if (wire > 0.5 && abs(dot(n, -dir)) > 0.25) discard;  // the outline only
    // (the depth is the square's, at the sphere's front: writing each pixel's own depth would make the depth
    // test late and the frame 1.5-2 times slower in software rendering)
    vec3 color = vColor;
    if (stripes > 0.5) {  // Gl1_Sphere.stripes: 12 sectors about the body's z axis, the two halves alternating
        vec3 b = vToBody * n;
        bool sector = sin(6.0 * atan(b.y, b.x)) > 0.0;
        if (sector != (b.z > 0.0)) color *= 0.55;
    }
    fragColor = vec4(wire > 0.5 ? vColor : shade(color, n, -dir), 1.0);
}
"""

_MESH_VS = """#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 color;
uniform mat4 view, proj;
out vec3 vNormal; out vec3 vColor; out vec3 vPos;
void main() {
    vec4 p = view * vec4(position, 1.0);
    vPos = p.xyz;
    vNormal = mat3(view) * normal;
    vColor = color;
    gl_Position = proj * p;
}
"""

_MESH_FS = """#version 330 core
in vec3 vNormal; in vec3 vColor; in vec3 vPos;
uniform float lit; uniform float ortho;
out vec4 fragColor;
""" + _LIGHTING + """
void main() {
    if (lit < 0.5) { fragColor = vec4(vColor, 1.0); return; }
    vec3 toEye = ortho > 0.5 ? vec3(0.0, 0.0, 1.0) : normalize(-vPos);
    vec3 n = normalize(vNormal);
    if (dot(n, toEye) < 0.0) n = -n;  // both sides lit
    fragColor = vec4(shade(vColor, n, toEye), 1.0);
}
"""


def _compile(vs, fs):
    prog = GL.glCreateProgram()
    for src, kind in ((vs, GL.GL_VERTEX_SHADER), (fs, GL.GL_FRAGMENT_SHADER)):
        sh = GL.glCreateShader(kind)
        GL.glShaderSource(sh, src)
        GL.glCompileShader(sh)
        if not GL.glGetShaderiv(sh, GL.GL_COMPILE_STATUS):
            raise RuntimeError("yade.qt: a shader did not compile: %s" % GL.glGetShaderInfoLog(sh).decode(errors='replace'))
        GL.glAttachShader(prog, sh)
    GL.glLinkProgram(prog)
    if not GL.glGetProgramiv(prog, GL.GL_LINK_STATUS):
        raise RuntimeError("yade.qt: shaders did not link: %s" % GL.glGetProgramInfoLog(prog).decode(errors='replace'))
    return prog


def _f32(a):
    return numpy.ascontiguousarray(a, dtype=numpy.float32)


class _Buffers:
    """A vertex array with one buffer per attribute, refilled at every frame."""

    def __init__(self, nAttrs):
        self.vao = GL.glGenVertexArrays(1)
        self.vbos = GL.glGenBuffers(nAttrs) if nAttrs > 1 else [GL.glGenBuffers(1)]

    def fill(self, arrays, divisors=None):
        GL.glBindVertexArray(self.vao)
        for loc, (vbo, a) in enumerate(zip(self.vbos, arrays)):
            a = _f32(a)
            GL.glBindBuffer(GL.GL_ARRAY_BUFFER, vbo)
            GL.glBufferData(GL.GL_ARRAY_BUFFER, a.nbytes, a if a.size else None, GL.GL_STREAM_DRAW)
            GL.glEnableVertexAttribArray(loc)
            GL.glVertexAttribPointer(loc, a.shape[1] if a.ndim > 1 else 1, GL.GL_FLOAT, GL.GL_FALSE, 0, ctypes.c_void_p(0))
            GL.glVertexAttribDivisor(loc, divisors[loc] if divisors else 0)


class SceneDrawer:
    """Owns the shaders and buffers of one view (made in its OpenGL context)."""

    def __init__(self):
        self.sphereProg = _compile(_SPHERE_VS, _SPHERE_FS)
        self.meshProg = _compile(_MESH_VS, _MESH_FS)
        self.spheres = _Buffers(7)
        self.triangles = _Buffers(3)
        self.lines = _Buffers(3)

    def _uniforms(self, prog, camera, aspect, renderer, extra=()):
        GL.glUseProgram(prog)
        view = camera.viewMatrix()

        def mat(name, m):
            GL.glUniformMatrix4fv(GL.glGetUniformLocation(prog, name), 1, GL.GL_TRUE, _f32(m))

        def f(name, x):
            loc = GL.glGetUniformLocation(prog, name)
            if loc >= 0:
                GL.glUniform1f(loc, float(x))

        def v3(name, x):
            loc = GL.glGetUniformLocation(prog, name)
            if loc >= 0:
                GL.glUniform3f(loc, *(float(c) for c in x))
        mat('view', view)
        mat('proj', camera.projectionMatrix(aspect))
        f('ortho', camera.ortho)
        # lights: their positions seen from the scene's center, in view coordinates
        for name, pos in (('lightDir1', renderer.lightPos), ('lightDir2', renderer.light2Pos)):
            d = numpy.asarray(pos, dtype=float)
            v3(name, view[:3, :3] @ (d / max(numpy.linalg.norm(d), 1e-12)))
        v3('lightColor1', renderer.lightColor)
        v3('lightColor2', renderer.light2Color)
        f('light1On', renderer.light1)
        f('light2On', renderer.light2)
        for name, x in extra:
            f(name, x)

    def draw(self, frame, camera, width, height, renderer, selection=-1, axes=False, grid=(False, False, False)):
        """Draws the frame into the current framebuffer (width × height pixels); axes and grid: the view's
        (GLViewer.axes: x, y, z in red, green, blue from the scene's center; GLViewer.grid: the planes yz, zx, xy
        through it)."""
        bg = renderer.bgColor
        GL.glViewport(0, 0, width, height)
        GL.glClearColor(float(bg[0]), float(bg[1]), float(bg[2]), 1.0)
        GL.glClear(GL.GL_COLOR_BUFFER_BIT | GL.GL_DEPTH_BUFFER_BIT)
        GL.glEnable(GL.GL_DEPTH_TEST)
        aspect = width / max(height, 1)
        pos, color = frame['pos'].copy(), frame['color'].copy()
        shown = (frame['mask'] & renderer.mask) != 0
        if frame.get('cellHSize') is not None:  # bodies wrapped into the periodic cell
            H = numpy.asarray(frame['cellHSize'])
            s = pos @ numpy.linalg.inv(H).T
            pos = (s - numpy.floor(s)) @ H.T
        if 0 <= selection < len(color):
            color[selection] = numpy.clip(color[selection] * 0.5 + 0.5, 0, 1)
        color[frame['highlight']] = numpy.clip(color[frame['highlight']] * 0.5 + 0.5, 0, 1)
        tris, lines = [], []  # (positions, normals, colors) per group
        if renderer.shape:  # each body by the drawer of its drawing functor (_SHAPE_DRAWERS, below)
            for name in frame['undrawn']:
                _warnOnce("yade.qt: no drawing functor draws %s bodies (a Gl1_%s class); they are not drawn" % (name, name))
            for number, name in enumerate(frame['drawers']):
                sel = (frame['drawer'] == number) & shown
                if not sel.any():
                    continue
                drawer = _SHAPE_DRAWERS.get(name)
                if drawer is None:
                    _warnOnce("yade.qt: %s has no drawer in yade/qt/drawing.py; its bodies are not drawn" % name)
                    continue
                drawer(self, frame, sel, pos, color, camera, aspect, renderer, tris, lines)
        if renderer.bound:
            lines.append(self._bounds(frame, shown))
        if renderer.intrAllWire:
            lines.append(self._segments(pos, frame['pairIds'], (0.6, 0.6, 0.6)))
        if renderer.intrPhys:
            tris.append(self._forceChains(frame, pos, camera))
        if frame.get('cellHSize') is not None:
            lines.append(self._cell(numpy.asarray(frame['cellHSize']), renderer.cellColor))
        if axes:
            lines.append(self._axes(camera))
        for normal, on in enumerate(grid):
            if on:
                lines.append(self._grid(camera, normal))
        tris = [t for t in tris if t is not None and len(t[0])]
        lines = [t for t in lines if t is not None and len(t[0])]
        if tris:
            self._uniforms(self.meshProg, camera, aspect, renderer, (('lit', 1),))
            self.triangles.fill([numpy.concatenate([t[i] for t in tris]) for i in range(3)])
            GL.glDrawArrays(GL.GL_TRIANGLES, 0, sum(len(t[0]) for t in tris))
        if lines:
            self._uniforms(self.meshProg, camera, aspect, renderer, (('lit', 0),))
            p = numpy.concatenate([t[0] for t in lines])
            self.lines.fill([p, numpy.zeros_like(p), numpy.concatenate([t[1] for t in lines])])
            GL.glDrawArrays(GL.GL_LINES, 0, len(p))
        GL.glBindVertexArray(0)
        GL.glUseProgram(0)

    def _spheres(self, frame, sel, pos, color, camera, aspect, renderer, tris, lines):
        """Gl1_Sphere: instanced impostors (size[0]: the radius)."""
        sph = sel & numpy.isfinite(frame['size'][:, 0])
        for wire in (False, True):
            part = sph & ((frame['wire'] | renderer.wire | wrapper.Gl1_Sphere.wire) == wire)
            n = int(part.sum())
            if not n:
                continue
            corners = numpy.array([[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]], dtype=numpy.float32)
            self._uniforms(self.sphereProg, camera, aspect, renderer, (('wire', wire), ('stripes', wrapper.Gl1_Sphere.stripes)))
            idx = numpy.nonzero(part)[0]
            idx = idx[numpy.argsort((pos[idx] - camera.eye) @ camera.viewDir, kind='stable')]  # front to back
            R = frame['rot'][idx]
            self.spheres.fill([corners, pos[idx], frame['size'][idx, 0], color[idx], R[:, :, 0], R[:, :, 1], R[:, :, 2]],
                              divisors=[0, 1, 1, 1, 1, 1, 1])
            GL.glDrawArraysInstanced(GL.GL_TRIANGLES, 0, 6, n)

    def _facets(self, frame, sel, pos, color, camera, aspect, renderer, tris, lines):
        """Gl1_Facet: the triangles it gathered (lit, or their edges when wire)."""
        ids = frame['triangleBody']
        keep = sel[ids]
        ids, c = ids[keep], frame['triangleCorners'][keep]
        wire = frame['wire'][ids] | renderer.wire
        edges = c[wire][:, [0, 1, 1, 2, 2, 0]].reshape(-1, 3)
        lines.append((edges, numpy.repeat(color[ids[wire]], 6, axis=0)))
        c, ids = c[~wire], ids[~wire]
        nrm = numpy.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0])
        nrm /= numpy.maximum(numpy.linalg.norm(nrm, axis=1), 1e-300)[:, None]
        tris.append((c.reshape(-1, 3), numpy.repeat(nrm, 3, axis=0), numpy.repeat(color[ids], 3, axis=0)))

    _CUBE = numpy.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1], [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], float)
    _CUBE_TRIS = numpy.array([0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 3, 0, 4, 3, 4, 7])
    _CUBE_NORMALS = numpy.repeat(numpy.array([[0, 0, -1], [0, 0, 1], [0, -1, 0], [0, 1, 0], [1, 0, 0], [-1, 0, 0]], float), 6, axis=0)
    _CUBE_EDGES = numpy.array([0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 0, 4, 1, 5, 2, 6, 3, 7])

    def _boxes(self, frame, sel, pos, color, camera, aspect, renderer, tris, lines):
        """Gl1_Box: 12 lit triangles each (size: the half-extents), or 12 edges when wire."""
        box = numpy.nonzero(sel)[0]
        R, e = frame['rot'][box], frame['size'][box]
        corners = pos[box][:, None, :] + numpy.einsum('nij,nkj->nki', R, self._CUBE[None] * e[:, None, :])
        wire = frame['wire'][box] | renderer.wire
        lines.append((corners[wire][:, self._CUBE_EDGES].reshape(-1, 3), numpy.repeat(color[box[wire]], 24, axis=0)))
        solid = ~wire
        normals = numpy.einsum('nij,kj->nki', R[solid], self._CUBE_NORMALS)
        tris.append((corners[solid][:, self._CUBE_TRIS].reshape(-1, 3), normals.reshape(-1, 3),
                     numpy.repeat(color[box[solid]], 36, axis=0)))

    def _walls(self, frame, sel, pos, color, camera, aspect, renderer, tris, lines):
        """Gl1_Wall: a square grid of Gl1_Wall.div lines each way (size: the axis and the sense)."""
        walls = numpy.nonzero(sel)[0]
        div = max(int(wrapper.Gl1_Wall.div), 1)
        half = camera.sceneRadius
        pts, cols = [], []
        for i in walls:  # (a few walls at most: a grid each)
            axis = int(frame['size'][i, 0])
            a1, a2 = (axis + 1) % 3, (axis + 2) % 3
            t = numpy.linspace(-half, half, div + 1)
            for u, v in ((a1, a2), (a2, a1)):
                p0 = numpy.tile(camera.sceneCenter, (div + 1, 1))
                p0[:, axis] = pos[i, axis]
                p1 = p0.copy()
                p0[:, u] += t
                p1[:, u] += t
                p0[:, v] -= half
                p1[:, v] += half
                pts.append(numpy.stack([p0, p1], axis=1).reshape(-1, 3))
                cols.append(numpy.repeat(color[i:i + 1], 2 * (div + 1), axis=0))
        lines.append((numpy.concatenate(pts), numpy.concatenate(cols)))

    def _bounds(self, frame, shown):
        ok = shown & numpy.isfinite(frame['boundMin']).all(axis=1) & numpy.isfinite(frame['boundMax']).all(axis=1)
        lo, hi = frame['boundMin'][ok], frame['boundMax'][ok]
        if not len(lo):
            return None
        unit = (self._CUBE + 1) / 2
        corners = lo[:, None, :] + unit[None] * (hi - lo)[:, None, :]
        p = corners[:, self._CUBE_EDGES].reshape(-1, 3)
        return p, numpy.tile([1.0, 1.0, 0.0], (len(p), 1))

    @staticmethod
    def _segments(pos, ids, rgb):
        if not len(ids):
            return None
        p = pos[ids].reshape(-1, 3)
        return p, numpy.tile(rgb, (len(p), 1))

    def _forceChains(self, frame, pos, camera):
        ids, fn = frame['contactIds'], frame['contactFn']
        g = wrapper.Gl1_NormPhys
        keep = numpy.ones(len(fn), bool)
        if g.signFilter > 0:
            keep &= fn > 0
        elif g.signFilter < 0:
            keep &= fn < 0
        ids, fn = ids[keep], numpy.abs(fn[keep])
        if not len(fn):
            return None
        if fn.max() > g.maxFn:
            g.maxFn = float(fn.max())
        radii = frame['size'][drawnBy(frame, 'Gl1_Sphere'), 0]
        if len(radii) and radii.min() < g.refRadius:
            g.refRadius = float(radii.min())
        maxR = g.maxRadius if g.maxRadius > 0 else (g.refRadius / 2 if numpy.isfinite(g.refRadius) else camera.sceneRadius / 100)
        half = maxR * fn / max(g.maxFn, 1e-300)
        a, b = pos[ids[:, 0]], pos[ids[:, 1]]
        side = numpy.cross(b - a, camera.viewDir)
        side /= numpy.maximum(numpy.linalg.norm(side, axis=1), 1e-300)[:, None]
        side *= half[:, None]
        quads = numpy.stack([a - side, a + side, b + side, a - side, b + side, b - side], axis=1).reshape(-1, 3)
        t = (fn / max(g.maxFn, 1e-300))[:, None]
        rgb = numpy.repeat(numpy.c_[t, 0.2 * numpy.ones_like(t), 1 - t], 6, axis=0)
        normals = numpy.tile(-camera.viewDir, (len(quads), 1))
        return quads, normals, rgb

    @staticmethod
    def _axes(camera):
        c, r = camera.sceneCenter, camera.sceneRadius
        p = numpy.array([c, c + (r, 0, 0), c, c + (0, r, 0), c, c + (0, 0, r)])
        return p, numpy.repeat(numpy.eye(3), 2, axis=0)

    @staticmethod
    def _grid(camera, normal, div=10):
        """A square grid of div cells each way in the plane through the scene's center across axis `normal`."""
        c, r = camera.sceneCenter, camera.sceneRadius
        u, v = (normal + 1) % 3, (normal + 2) % 3
        t = numpy.linspace(-r, r, div + 1)
        pts = []
        for a, b in ((u, v), (v, u)):
            p0 = numpy.tile(c, (div + 1, 1))
            p0[:, a] += t
            p1 = p0.copy()
            p0[:, b] -= r
            p1[:, b] += r
            pts.append(numpy.stack([p0, p1], axis=1).reshape(-1, 3))
        p = numpy.concatenate(pts)
        return p, numpy.tile([0.5, 0.5, 0.5], (len(p), 1))

    def _cell(self, H, rgb):
        corners = ((self._CUBE + 1) / 2) @ H.T
        p = corners[self._CUBE_EDGES]
        return p, numpy.tile(numpy.asarray(rgb, float), (len(p), 1))


# The drawer of each drawing functor (the Gl1_* classes that gather what they draw: pkg/common/GlFunctors.hpp).
_SHAPE_DRAWERS = {'Gl1_Sphere': SceneDrawer._spheres, 'Gl1_Facet': SceneDrawer._facets, 'Gl1_Box': SceneDrawer._boxes,
                  'Gl1_Wall': SceneDrawer._walls}
