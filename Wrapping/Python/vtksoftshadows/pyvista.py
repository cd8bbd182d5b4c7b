# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
"""Soft shadows for PyVista plotters.

    import pyvista as pv
    from vtksoftshadows.pyvista import enable_soft_shadows, disable_soft_shadows

    pl = pv.Plotter(lighting="none")
    pl.add_mesh(pv.Plane(i_size=6, j_size=6, direction=(0, 1, 0)))
    pl.add_mesh(pv.Sphere(radius=0.5, center=(0, 1, 0)))
    pl.add_light(pv.Light(position=(1, 5, 0.5), focal_point=(0, 0, 0),
                          positional=True, cone_angle=45))
    enable_soft_shadows(pl, "contact", light_radius=0.3, map_size=2048)
    pl.show(auto_close=False)
    disable_soft_shadows(pl)      # back to what the plotter drew before

With PyVista 0.48 and later the same is reachable from the plotter once this
module is imported: ``pl.enable_soft_shadows(...)``,
``pl.disable_soft_shadows()`` and the namespace ``pl.soft_shadows``
(``enable``, ``disable``, ``shadow_pass``, ``enabled``).

Where the pass goes. PyVista draws the scene through its own pass chain
(``pyvista/plotting/render_passes.py``): a ``vtkCameraPass`` around a
``vtkSequencePass`` whose collection holds one ``vtkRenderStepsPass`` (the
ordinary drawing), wrapped by the passes PyVista manages (EDL, depth of field,
blur, FXAA, SSAO, SSAA), and ``renderer.SetPass(None)`` when none is on. The
soft shadow pass takes the place of that ``vtkRenderStepsPass`` in the
collection (it draws the scene itself, through its own render steps, with the
shadows in every receiver's shader), so every pass PyVista wraps around the
scene works on the shadowed picture, and PyVista's later ``enable_*`` and
``disable_*`` calls keep it. Where PyVista would render without any pass, the
chain is set on the renderer here, and again before each frame if a PyVista
call reset it (``RenderPasses._update_passes()`` sets ``None`` when its last
pass goes).

What combines and what is refused (``SoftShadowsCompatibilityError`` when
enabling; a conflict made afterwards turns the soft shadows off at the next
frame, with a ``RuntimeWarning`` saying why), as pictures drawn with PyVista
0.44.1 on VTK 9.3 and 0.49.0 on VTK 9.6 show (Testing/Python/test_pyvista.py):

- SSAO, eye dome lighting, blurring, MSAA: combined with every technique.
  (SSAO registers its shader hooks on the props, and its
  ``SetShaderParameters`` sets its own draw buffers during the module's
  light-space draws too: VTK warns "Attempt to set draw buffers from a
  Framebuffer Object that is not bound" once every shadow-map and camera-depth
  draw; the pictures are right on OpenGL 4.1 and later.)
- FXAA (``enable_anti_aliasing('fxaa')``): VTK applies the renderer's FXAA
  only when the renderer has no pass, so while soft shadows are on a
  ``vtkOpenGLFXAAPass`` stands in for it in PyVista's chain (taken out when
  FXAA or the soft shadows are turned off).
- SSAA and depth of field draw the scene larger than the viewport (sqrt(5)
  times; 16 pixels more on each side through a wider camera): combined with
  the techniques that work in light space only (hard, omni, silhouette,
  smoothies); refused for those whose receivers read screen-space buffers of
  the viewport's size (contact, reference, aliasfree), which would silently
  fall back to hard shadows.
- Eye dome lighting, blurring and depth of field draw into a buffer of their
  own at its corner: in a subplot that does not start at the window's
  corner, refused with the screen-space techniques for the same reason.
- PyVista's own shadows (``enable_shadows``, VTK's vtkShadowMapPass): refused;
  they would draw the scene again over the soft shadows.
- A pass set on the renderer by hand (``renderer.SetPass``), outside PyVista's
  passes: refused (PyVista's pass management would replace it).

Lights. Every light that is switched on and is not a headlight casts a shadow:
scene lights, and camera lights (from their world position each frame).
PyVista's default ``lighting='light kit'`` is one headlight and four
directional camera lights (key, fill, two back lights), so it gives four
shadows; ``lighting='three lights'`` gives three. For one shadow, make the
plotter with ``lighting='none'`` and add a ``pyvista.Light``.
"""
from __future__ import annotations

import math
import warnings
import weakref

import pyvista
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkRenderingCore import vtkLight, vtkLightCollection, vtkRenderer
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLFXAAPass

from . import vtkLightVisibilityFilter, vtkShadowTechniqueCatalog, vtkSoftShadowPass

__all__ = [
    "SoftShadowsCompatibilityError",
    "disable_soft_shadows",
    "enable_soft_shadows",
    "get_soft_shadow_pass",
    "light_visibility",
]

_CATALOG = vtkShadowTechniqueCatalog


_STATES = {}  # id(renderer) -> _State


class SoftShadowsCompatibilityError(RuntimeError):
    """Soft shadows and another of the renderer's passes cannot draw together."""


# --------------------------------------------------------------------------
# Techniques, variants and parameters, from vtkShadowTechniqueCatalog.


def _technique_names():
    return [_CATALOG.GetTechniqueName(t) for t in range(_CATALOG.GetNumberOfTechniques())]


def _light_space_names():
    """The techniques whose receivers look up light-space maps only: every
    other one reads screen-space buffers of the viewport's size
    (vtkSoftShadowPass.GetUsesScreenSpace()), and needs the scene drawn at
    the viewport's size and corner."""
    return [_CATALOG.GetTechniqueName(t) for t in range(_CATALOG.GetNumberOfTechniques())
            if not _CATALOG.NewPass(t, 0).GetUsesScreenSpace()]


def _variant_names(technique):
    return [_CATALOG.GetVariantName(technique, v)
            for v in range(_CATALOG.GetNumberOfVariants(technique))]


def _parameter_keys(technique):
    return [_CATALOG.GetParameterKey(technique, p)
            for p in range(_CATALOG.GetNumberOfParameters(technique))]


def _allowed_text(technique, parameter):
    """What IsAllowed() takes, in words."""
    kind = _CATALOG.GetParameterType(technique, parameter)
    if kind == _CATALOG.Boolean:
        return "True or False"
    low = _CATALOG.GetParameterMinimum(technique, parameter)
    high = _CATALOG.GetParameterMaximum(technique, parameter)
    if math.isinf(low) and math.isinf(high):
        span = "any"
    elif math.isinf(high):
        span = "at least %g" % low
    else:
        span = "from %g to %g" % (low, high)
    if kind == _CATALOG.Integer:
        return "a whole number, %s" % span
    if kind == _CATALOG.Vector3:
        return "three finite numbers, each %s" % span
    return "a finite number, %s" % span


def _number(label, value):
    """float(value) for a real number (bools are 0 and 1); ValueError otherwise."""
    if isinstance(value, (str, bytes)) or value is None or isinstance(value, complex):
        raise ValueError("%s: %r is not a number" % (label, value))
    try:
        return float(value)
    except (TypeError, ValueError):
        raise ValueError("%s: %r is not a number" % (label, value)) from None


class _Spec:
    """A technique spec and its parameters, checked against the catalog
    before anything is made or changed."""

    def __init__(self, technique, parameters):
        if not isinstance(technique, str):
            raise ValueError("technique must be a string 'name[:variant]', got %r" % (technique,))
        name, colon, variant = technique.strip().partition(":")
        names = _technique_names()
        self.index = _CATALOG.FindTechnique(name)
        if self.index < 0:
            if name == "vtk":
                raise ValueError("technique 'vtk' is VTK's own vtkShadowMapPass, which PyVista "
                                 "turns on with plotter.enable_shadows(); choose one of: %s"
                                 % ", ".join(names))
            raise ValueError("unknown shadow technique %r; choose one of: %s"
                             % (name, ", ".join(names)))
        self.name = name
        variants = _variant_names(self.index)
        parameters = dict(parameters)
        if "variant" in parameters:  # a scene file's "<technique>": {"variant": ...}
            given = parameters.pop("variant")
            if colon and given != variant:
                raise ValueError("technique %r and variant=%r disagree" % (technique, given))
            colon, variant = ":", given
        if colon:
            if not variants:
                raise ValueError("technique %r has no variants (got %r)" % (name, variant))
            if variant not in variants:
                raise ValueError("technique %r has no variant %r; its variants: %s"
                                 % (name, variant, ", ".join(variants)))
        else:
            variant = variants[0] if variants else None
        self.variant = variant
        self.variant_index = variants.index(variant) if variant is not None else -1
        self.screen_space = _CATALOG.NewPass(self.index, self.variant_index).GetUsesScreenSpace()

        keys = _parameter_keys(self.index)
        unknown = sorted(key for key in parameters if key not in keys)
        if unknown:
            raise ValueError("technique %r has no parameter%s %s; its parameters: %s"
                             % (name, "s" if len(unknown) > 1 else "",
                                ", ".join(repr(k) for k in unknown), ", ".join(keys)))
        self.values = []  # (parameter index, [3 doubles])
        for key, value in parameters.items():
            parameter = _CATALOG.FindParameter(self.index, key)
            label = "%s.%s" % (name, key)
            if _CATALOG.GetParameterSize(self.index, parameter) == 3:
                if isinstance(value, (str, bytes)):
                    raise ValueError("%s: %r is not three numbers" % (label, value))
                try:
                    items = list(value)
                except TypeError:
                    raise ValueError("%s: %r is not three numbers" % (label, value)) from None
                if len(items) != 3:
                    raise ValueError("%s: %r is not three numbers" % (label, value))
                numbers_ = [_number(label, item) for item in items]
            else:
                numbers_ = [_number(label, value), 0.0, 0.0]
            if not _CATALOG.IsAllowed(self.index, parameter, numbers_):
                raise ValueError("%s = %r is not allowed: %s"
                                 % (label, value, _allowed_text(self.index, parameter)))
            self.values.append((parameter, numbers_))

    def label(self):
        return self.name + (":" + self.variant if self.variant else "")

    def new_pass(self):
        """A new pass with the parameters set, through the catalog."""
        made = _CATALOG.NewPass(self.index, self.variant_index)
        if made is None:
            raise RuntimeError("vtkShadowTechniqueCatalog made no pass for %s" % self.label())
        for parameter, numbers_ in self.values:
            if not _CATALOG.SetParameter(made, self.index, parameter, numbers_):
                raise RuntimeError("vtkShadowTechniqueCatalog refused %s.%s"
                                   % (self.name, _CATALOG.GetParameterKey(self.index, parameter)))
        return made


def _light_radius(value):
    if value is None:
        return None
    radius = _number("light_radius", value)
    if not (math.isfinite(radius) and radius >= 0.0):
        raise ValueError("light_radius = %r is not allowed: None or a finite number >= 0 (world "
                         "units for spot and point lights, degrees for directional ones)"
                         % (value,))
    return radius


# --------------------------------------------------------------------------
# PyVista's renderer and its pass chain.


def _same(a, b):
    """Whether two wrapped VTK objects are one C++ object."""
    if a is b:
        return True
    this = getattr(a, "__this__", None)
    return this is not None and this == getattr(b, "__this__", None)


def _items(collection):
    if collection is None:
        return []
    return [collection.GetItemAsObject(i) for i in range(collection.GetNumberOfItems())]


def _replace_item(collection, old, new):
    """Puts `new` where `old` is in a vtkRenderPassCollection, in place (the
    vtkSequencePass holds that very collection)."""
    items = _items(collection)
    collection.RemoveAllItems()
    for item in items:
        collection.AddItem(new if _same(item, old) else item)


def _contains(collection, item):
    return any(_same(i, item) for i in _items(collection))


def _chain(top):
    """Every pass reachable from `top` through delegates and sequences."""
    seen, stack = [], [top]
    while stack:
        current = stack.pop()
        if current is None or any(_same(current, s) for s in seen):
            continue
        seen.append(current)
        delegate = getattr(current, "GetDelegatePass", None)
        if delegate is not None:
            stack.append(delegate())
        passes = getattr(current, "GetPasses", None)
        if passes is not None:
            stack.extend(_items(passes()))
    return seen


def _render_passes(renderer):
    """PyVista's RenderPasses of `renderer`, with what is used here."""
    passes = getattr(renderer, "_render_passes", None)
    needed = ("_pass_collection", "_camera_pass", "_update_passes", "_add_pass",
              "_remove_pass", "_passes")
    if passes is None or not all(hasattr(type(passes), n) or hasattr(passes, n)
                                 for n in needed):
        raise RuntimeError("vtksoftshadows.pyvista needs PyVista's render pass manager "
                           "(pyvista.plotting.render_passes.RenderPasses, PyVista 0.36 and "
                           "later); this PyVista (%s) has none it knows"
                           % getattr(pyvista, "__version__", "?"))
    return passes


def _collection(passes, create):
    """The base pass collection; without `create`, None rather than making one
    (RenderPasses makes it lazily, and anew after deep_clean())."""
    if create:
        return passes._pass_collection
    stored = getattr(passes, "_RenderPasses__pass_collection", passes)
    return passes._pass_collection if stored is passes else stored


def _managed(passes):
    """The passes PyVista manages around its camera pass (EDL, depth of field,
    blur, FXAA, SSAO, SSAA)."""
    return [p for group in passes._passes.values() for p in group]


def _camera(passes):
    """PyVista's camera pass, without making one."""
    stored = getattr(passes, "_RenderPasses__camera_pass", passes)
    return passes._camera_pass if stored is passes else stored


def _is_pyvista_chain(passes, current):
    return _same(current, _camera(passes)) or any(_same(current, p) for p in _managed(passes))


def _conflict(renderer, passes, spec, ours=None):
    """Why soft shadows of `spec` cannot draw in `renderer` now, as (kind,
    message), or None."""
    for item in _items(_collection(passes, create=True)):
        if item.IsA("vtkShadowMapPass") or item.IsA("vtkShadowMapBakerPass"):
            return "shadows", (
                "PyVista's shadows are on in this renderer (plotter.enable_shadows(): VTK's "
                "vtkShadowMapPass in the same pass collection); they would draw the scene again "
                "over the soft shadows. Call plotter.disable_shadows() first.")
        if item.IsA("vtkSoftShadowPass") and not _same(item, ours):
            return "other", (
                "this renderer's pass collection already holds a soft shadow pass (%s) that "
                "vtksoftshadows.pyvista did not put there" % item.GetClassName())
    current = renderer.GetPass()
    if current is not None and not _is_pyvista_chain(passes, current):
        return "foreign", (
            "this renderer draws through a pass set with renderer.SetPass() (%s), outside "
            "PyVista's render passes; PyVista's pass management, which the soft shadows join, "
            "would replace it. Set the renderer's pass to None first, or put a vtksoftshadows "
            "pass in a chain of your own." % current.GetClassName())
    if spec.screen_space:
        managed = _managed(passes)
        mismatch = None
        if any(p.IsA("vtkSSAAPass") for p in managed):
            mismatch = ("SSAA (enable_anti_aliasing('ssaa')) draws the scene at sqrt(5) times the "
                        "viewport's size")
        elif any(p.IsA("vtkDepthOfFieldPass") for p in managed):
            mismatch = ("depth of field (enable_depth_of_field()) draws the scene 16 pixels wider "
                        "on every side, through a wider camera")
        else:
            origin = tuple(renderer.GetOrigin())
            own_buffer = sorted({p.GetClassName() for p in managed
                                 if (p.IsA("vtkImageProcessingPass")
                                     or p.IsA("vtkDepthImageProcessingPass"))
                                 and not p.IsA("vtkOpenGLFXAAPass") and not p.IsA("vtkSSAOPass")})
            if origin != (0, 0) and own_buffer:
                mismatch = ("this subplot's viewport starts at %s in the window, and %s draw the "
                            "scene into a buffer of their own, at its corner"
                            % (origin, ", ".join(own_buffer)))
        if mismatch is not None:
            return "screen", (
                "%s draws its shadows through screen-space buffers that match the viewport, "
                "and %s: the two do not line up, and the shadows would lose their soft edges. "
                "Use a light-space technique (%s) with it, or turn it off%s." % (
                    spec.label(), mismatch, ", ".join(_light_space_names()),
                    " (FXAA or MSAA anti-aliasing combine with every technique)"
                    if "SSAA" in mismatch else ""))
    return None


def _resolve(target):
    """(renderer, plotter or None) for a PyVista plotter or renderer."""
    if hasattr(target, "_render_passes") and hasattr(target, "SetPass"):
        return target, None
    renderer = getattr(target, "renderer", None)
    if renderer is None or not hasattr(renderer, "SetPass"):
        raise TypeError("expected a pyvista.Plotter (or one of its renderers), got %s"
                        % type(target).__name__)
    return renderer, target


def _closed(renderer, plotter):
    return (getattr(plotter, "_closed", False) or getattr(renderer, "_closed", False)
            or (plotter is not None and getattr(plotter, "render_window", True) is None)
            or renderer.GetRenderWindow() is None)


def _release(window, *passes):
    """ReleaseGraphicsResources(window) of `passes` while the window's context
    lives; after Finalize() (a closed plotter) VTK has released the chain
    itself. Returns whether it released."""
    if window is None:
        return False
    window.MakeCurrent()
    if not window.IsCurrent():
        return False
    for p in passes:
        if p is not None:
            p.ReleaseGraphicsResources(window)
    return True


def _lights(renderer):
    collection = renderer.GetLights()
    return [collection.GetItemAsObject(i) for i in range(collection.GetNumberOfItems())]


class _State:
    """Soft shadows on one renderer: the pass, what it replaced, the lights
    sized here, and the observer that keeps the chain right."""

    def __init__(self, renderer, plotter):
        key = id(renderer)
        self.key = key
        self.renderer_ref = weakref.ref(renderer, lambda _: _STATES.pop(key, None))
        self.plotter_ref = weakref.ref(plotter) if plotter is not None else None
        self.shadow_pass = None
        self.spec = None
        self.original = None  # PyVista's vtkRenderStepsPass
        self.fxaa = None  # a vtkOpenGLFXAAPass put in PyVista's chain here
        self.sized = []  # (light, radius given here)
        self.observer = None
        self.rendered = False
        self.warned = None  # the last problem said about a frame

    # The chain -------------------------------------------------------------

    def attach(self, shadow_pass, spec):
        renderer = self.renderer_ref()
        passes = _render_passes(renderer)
        collection = _collection(passes, create=True)
        steps = [i for i in _items(collection)
                 if i.IsA("vtkRenderStepsPass") and not i.IsA("vtkSoftShadowPass")]
        if not steps:
            raise SoftShadowsCompatibilityError(
                "PyVista's base pass collection has no vtkRenderStepsPass for the soft shadows "
                "to take the place of (it holds: %s)"
                % (", ".join(i.GetClassName() for i in _items(collection)) or "nothing"))
        self.original = steps[0]
        _replace_item(collection, self.original, shadow_pass)
        self.shadow_pass, self.spec = shadow_pass, spec
        _STATES[self.key] = self
        try:
            self._sync_fxaa(renderer, passes)
            self._apply(renderer, passes)
            problem = self._unreached(renderer)
            if problem is not None:
                raise SoftShadowsCompatibilityError(problem)
        except Exception:
            self.disable(release=False)
            raise
        self.observer = renderer.AddObserver(vtkCommand.StartEvent, self._on_start)

    def replace(self, shadow_pass, spec):
        """A second enable: the new pass where the old one was."""
        renderer = self.renderer_ref()
        passes = _render_passes(renderer)
        old = self.shadow_pass
        _replace_item(_collection(passes, create=True), old, shadow_pass)
        self.shadow_pass, self.spec = shadow_pass, spec
        self._apply(renderer, passes)
        if self.rendered:
            _release(renderer.GetRenderWindow(), old)

    @staticmethod
    def _apply(renderer, passes):
        """PyVista's chain on the renderer, with a pass even when PyVista would
        set none."""
        passes._update_passes()
        if renderer.GetPass() is None:
            renderer.SetPass(passes._camera_pass)

    def _unreached(self, renderer):
        """What of ours the renderer's chain does not reach, in words, or None."""
        chain = _chain(renderer.GetPass())
        if not any(_same(self.shadow_pass, p) for p in chain):
            return "PyVista's pass chain does not reach the soft shadow pass"
        if self.fxaa is not None and not any(_same(self.fxaa, p) for p in chain):
            return ("FXAA is on (enable_anti_aliasing('fxaa')), which VTK skips while the renderer "
                    "has a pass, and this PyVista's pass chain does not place the "
                    "vtkOpenGLFXAAPass that would stand in for it; use MSAA or SSAA anti-aliasing")
        return None

    def _sync_fxaa(self, renderer, passes):
        """VTK ignores the renderer's FXAA flag while it has a pass: stand in
        for it with a vtkOpenGLFXAAPass in PyVista's chain."""
        wanted = bool(renderer.GetUseFXAA())
        if wanted and self.fxaa is None:
            fxaa = vtkOpenGLFXAAPass()
            if hasattr(fxaa, "SetFXAAOptions") and renderer.GetFXAAOptions() is not None:
                fxaa.SetFXAAOptions(renderer.GetFXAAOptions())
            self.fxaa = fxaa
            passes._add_pass(fxaa)
        elif not wanted and self.fxaa is not None:
            fxaa, self.fxaa = self.fxaa, None
            passes._remove_pass(fxaa)
            if self.rendered:
                # Releasing an image-processing pass releases its delegate:
                # the chain, which goes on drawing.
                fxaa.SetDelegatePass(None)
                _release(renderer.GetRenderWindow(), fxaa)

    def _on_start(self, caller, event):
        # Exceptions cannot leave a VTK observer: say them as warnings.
        try:
            self._check_frame()
        except Exception as error:  # noqa: BLE001
            warnings.warn("vtksoftshadows.pyvista: %s: %s" % (type(error).__name__, error),
                          RuntimeWarning, stacklevel=2)

    def _say(self, problem):
        if problem != self.warned:
            self.warned = problem
            warnings.warn(problem, RuntimeWarning, stacklevel=3)

    def _check_frame(self):
        """Before each frame: the chain still as it must be after whatever
        PyVista calls came since; a pass drawn with the shadows that cannot
        be turns them off, with a warning."""
        renderer = self.renderer_ref()
        if renderer is None or self.shadow_pass is None:
            return
        passes = _render_passes(renderer)
        collection = _collection(passes, create=False)
        if collection is None or not _contains(collection, self.shadow_pass):
            # PyVista remade its passes (deep_clean()), or ours was taken out.
            self.disable(release=True)
            return
        problem = _conflict(renderer, passes, self.spec, ours=self.shadow_pass)
        if problem is not None and problem[0] == "foreign":
            self._say("soft shadows are not drawn: " + problem[1])
            return
        if problem is not None:
            label = self.spec.label()
            self.disable(release=True)
            self._say("soft shadows (%s) were turned off: %s" % (label, problem[1]))
            return
        self._sync_fxaa(renderer, passes)
        if renderer.GetPass() is None:
            renderer.SetPass(passes._camera_pass)
        unreached = self._unreached(renderer)
        if unreached is not None:
            self._say("soft shadows are not drawn: " + unreached)
            return
        self.warned = None
        self.rendered = True

    # Lights ----------------------------------------------------------------

    def _sized_elsewhere(self):
        """(light, radius) sized by the soft shadows of other renderers: a
        light PyVista adds to every subplot is one light for all of them."""
        return [entry for state in list(_STATES.values()) if state is not self
                for entry in state.sized]

    def size_lights(self, radius):
        self.restore_lights()
        if radius is None:
            return
        key = vtkSoftShadowPass.RADIUS()
        elsewhere = self._sized_elsewhere()
        for light in _lights(self.renderer_ref()):
            if light.LightTypeIsHeadlight():
                continue  # headlights cast no shadow
            shared = [r for other, r in elsewhere if other is light]
            if shared:
                if shared[0] != radius:
                    warnings.warn("a light of this renderer is also another subplot's, whose "
                                  "soft shadows gave it radius %g; it keeps it" % shared[0],
                                  RuntimeWarning, stacklevel=3)
                self.sized.append((light, shared[0]))
                continue
            if light.GetInformation().Has(key):
                continue  # a light with a size of its own keeps it
            vtkSoftShadowPass.SetRadius(radius, light)
            self.sized.append((light, radius))

    def restore_lights(self):
        key = vtkSoftShadowPass.RADIUS()
        elsewhere = self._sized_elsewhere()
        for light, radius in self.sized:
            if any(other is light for other, _ in elsewhere):
                continue  # another renderer's soft shadows still use its size
            information = light.GetInformation()
            if information.Has(key) and information.Get(key) == radius:
                information.Remove(key)
        self.sized = []

    # Off ---------------------------------------------------------------------

    def disable(self, release=True):
        """Everything back as PyVista had it; the GPU resources released."""
        if _STATES.get(self.key) is self:
            del _STATES[self.key]
        renderer = self.renderer_ref()
        shadow_pass, fxaa = self.shadow_pass, self.fxaa
        self.shadow_pass, self.fxaa = None, None
        self.restore_lights()
        if renderer is None or shadow_pass is None:
            return
        if self.observer is not None:
            renderer.RemoveObserver(self.observer)
            self.observer = None
        passes = getattr(renderer, "_render_passes", None)
        if passes is not None:
            # After deep_clean() PyVista's passes are gone: nothing to put back,
            # and asking for them would make new ones.
            alive = getattr(passes, "_renderer", None) is not None
            try:
                collection = _collection(passes, create=False)
                if collection is not None and _contains(collection, shadow_pass):
                    _replace_item(collection, shadow_pass, self.original)
                if alive and fxaa is not None and any(_same(fxaa, p) for p in _managed(passes)):
                    passes._remove_pass(fxaa)
                if alive:
                    passes._update_passes()
            except (RuntimeError, AttributeError):
                pass  # "The renderer has been closed.": nothing is drawn any more
        if release and self.rendered:
            if fxaa is not None:
                fxaa.SetDelegatePass(None)  # not PyVista's chain with it
            _release(renderer.GetRenderWindow(), shadow_pass, fxaa)


def _state(renderer):
    state = _STATES.get(id(renderer))
    if state is not None and state.renderer_ref() is not renderer:
        _STATES.pop(id(renderer), None)  # an old renderer's id, reused
        return None
    return state


# --------------------------------------------------------------------------
# The interface.


def enable_soft_shadows(plotter, technique="contact", light_radius=None, **parameters):
    """Draw the plotter's scene with the module's soft shadows.

    Parameters
    ----------
    plotter : pyvista.Plotter or pyvista.Renderer
        For a plotter, its active renderer (``plotter.renderer``; call once
        per subplot for several).
    technique : str, default: "contact"
        ``name[:variant]`` as the scene files and ``softshadows --technique``
        spell it: ``hard``, ``reference``, ``contact`` (``pcf``, ``gaussian``,
        ``multipass``), ``omni`` (``poisson``, ``pcf4``, ``hard``),
        ``silhouette`` (``soft``, ``hard``), ``smoothies``, ``aliasfree``
        (``soft``, ``hard``). The first variant is the default.
    light_radius : float, optional
        The size given to every light of the renderer that has none yet
        (``vtkSoftShadowPass.SetRadius``): world units for spot and point
        lights, angular radius in degrees for directional lights (the light
        kit's). ``None`` leaves the lights as they are; a light without a size
        is a point (hard shadows). Headlights are left alone: they cast no
        shadow.
    **parameters
        The technique's parameters as scene files name them (the keys of
        ``vtkShadowTechniqueCatalog``, e.g. ``dp``, ``pass_limit``,
        ``pcf_radius``, ``map_size``), and ``variant``. Vector parameters
        take three numbers.

    Returns
    -------
    vtksoftshadows.vtkSoftShadowPass
        The pass (e.g. a ``vtkContactHardeningShadowPass``), to read or tune.

    Raises
    ------
    ValueError
        An unknown technique, variant or parameter, or a value out of its
        range (named in the message); nothing is changed.
    SoftShadowsCompatibilityError
        Another pass of the renderer cannot draw with the technique (see the
        module's documentation); nothing is changed.
    RuntimeError
        The plotter is closed, or its PyVista has no render pass manager
        this module knows.

    Calling it again replaces the technique, its parameters and the light
    sizes given by the previous call; the previous pass's GPU resources are
    released.
    """
    renderer, owner = _resolve(plotter)
    spec = _Spec(technique, parameters)
    radius = _light_radius(light_radius)
    if _closed(renderer, owner):
        raise RuntimeError("the plotter is closed")
    passes = _render_passes(renderer)
    state = _state(renderer)
    if state is not None and not _contains(_collection(passes, create=False),
                                           state.shadow_pass):
        state.disable(release=True)  # PyVista remade its passes since
        state = None
    problem = _conflict(renderer, passes, spec, ours=state.shadow_pass if state else None)
    if problem is not None:
        raise SoftShadowsCompatibilityError(problem[1])

    shadow_pass = spec.new_pass()
    if state is None:
        state = _State(renderer, owner)
        state.attach(shadow_pass, spec)
    else:
        state.replace(shadow_pass, spec)
    state.size_lights(radius)
    if owner is not None and _REGISTERED and isinstance(owner, _BASE_PLOTTER):
        # Construct the plotter's component, so its close hooks run.
        getattr(owner, "soft_shadows", None)
    return shadow_pass


def disable_soft_shadows(plotter):
    """Turn the soft shadows off, in every renderer of a plotter (or in the
    one renderer given): it draws as it did before they were enabled (PyVista's own passes kept), the lights lose the size
    ``enable_soft_shadows`` gave them, and the pass's GPU resources are
    released (``ReleaseGraphicsResources``). Without soft shadows on, it does
    nothing."""
    renderer, owner = _resolve(plotter)
    renderers = list(getattr(owner, "renderers", None) or [renderer]) if owner else [renderer]
    for each in renderers:
        state = _state(each)
        if state is not None:
            state.disable(release=True)


def get_soft_shadow_pass(plotter):
    """The soft shadow pass drawing the plotter's active renderer, or None."""
    renderer, _ = _resolve(plotter)
    state = _state(renderer)
    return state.shadow_pass if state is not None else None


def _teardown(plotter):
    """Soft shadows off on every renderer of `plotter` (its close and
    deep_clean hooks; safe to run again)."""
    if plotter is None:
        return
    for state in list(_STATES.values()):
        if state.plotter_ref is not None and state.plotter_ref() is plotter:
            state.disable(release=True)


# --------------------------------------------------------------------------
# PyVista 0.48's plotter components: plotter.soft_shadows,
# plotter.enable_soft_shadows(...), plotter.disable_soft_shadows().


class SoftShadowsComponent:
    """``plotter.soft_shadows``: the soft shadows of the plotter's active
    renderer (vtksoftshadows.pyvista)."""

    def __init__(self, plotter):
        self._plotter = weakref.ref(plotter)

    def _get(self):
        plotter = self._plotter()
        if plotter is None:
            raise RuntimeError("the plotter is gone")
        return plotter

    def enable(self, technique="contact", light_radius=None, **parameters):
        """As ``enable_soft_shadows(plotter, ...)``."""
        return enable_soft_shadows(self._get(), technique, light_radius, **parameters)

    def disable(self):
        """As ``disable_soft_shadows(plotter)``."""
        disable_soft_shadows(self._get())

    @property
    def shadow_pass(self):
        """The pass drawing the active renderer, or None."""
        return get_soft_shadow_pass(self._get())

    @property
    def enabled(self):
        """Whether the active renderer draws soft shadows."""
        return self.shadow_pass is not None

    def __plotter_close__(self):  # noqa: PLW3201 (PyVista's hook name)
        _teardown(self._plotter())

    def __plotter_deep_clean__(self):  # noqa: PLW3201
        _teardown(self._plotter())


class _EnableSoftShadows:
    def __init__(self, plotter):
        self._plotter = weakref.ref(plotter)

    def __call__(self, technique="contact", light_radius=None, **parameters):
        return enable_soft_shadows(self._plotter(), technique, light_radius, **parameters)


class _DisableSoftShadows:
    def __init__(self, plotter):
        self._plotter = weakref.ref(plotter)

    def __call__(self):
        disable_soft_shadows(self._plotter())


_EnableSoftShadows.__doc__ = enable_soft_shadows.__doc__
_DisableSoftShadows.__doc__ = disable_soft_shadows.__doc__


def _base_plotter():
    base = getattr(pyvista, "BasePlotter", None)
    if base is None:
        try:
            from pyvista.plotting.plotter import BasePlotter as base  # noqa: N813
        except ImportError:
            return None
    return base


_BASE_PLOTTER = _base_plotter()
_REGISTERED = False


def _register_components():
    """Registers the components where PyVista has the registry (0.48+).
    Returns whether all three are registered."""
    register = getattr(pyvista, "register_plotter_component", None)
    if register is None or _BASE_PLOTTER is None:
        return False
    done = 0
    for name, component in (("soft_shadows", SoftShadowsComponent),
                            ("enable_soft_shadows", _EnableSoftShadows),
                            ("disable_soft_shadows", _DisableSoftShadows)):
        # A registered component reads back as its class on the plotter class.
        existing = getattr(_BASE_PLOTTER, name, None)
        ours = (isinstance(existing, type) and existing.__module__ == __name__
                and existing.__qualname__ == component.__qualname__)
        if existing is not None and not ours:
            warnings.warn("vtksoftshadows.pyvista: pyvista.BasePlotter already has %r (%r); "
                          "plotter.%s is not registered, use vtksoftshadows.pyvista's functions"
                          % (name, existing, name), RuntimeWarning, stacklevel=3)
            continue
        try:
            register(name, override=ours)(component)
            done += 1
        except (TypeError, ValueError) as error:
            warnings.warn("vtksoftshadows.pyvista: plotter.%s not registered: %s"
                          % (name, error), RuntimeWarning, stacklevel=3)
    return done == 3


_REGISTERED = _register_components()


# --------------------------------------------------------------------------
# Shadows as data.

_SUN_KEYS = {"latitude": "SetSunLatitude", "day": "SetSunDayOfYear", "step": "SetSunTimeStep",
             "up": "SetSunUp", "north": "SetSunNorth", "radius": "SetSunRadius"}


def _surface(mesh, label):
    data = pyvista.wrap(mesh)
    if data is None:
        raise TypeError("%s: expected a PyVista or VTK dataset, got %r" % (label, mesh))
    return data if isinstance(data, pyvista.PolyData) else data.extract_surface()


def _light_list(lights):
    if hasattr(lights, "renderer") and isinstance(lights.renderer, vtkRenderer):
        lights = lights.renderer  # a plotter: its active renderer's lights
    if isinstance(lights, vtkRenderer):
        return _lights(lights)
    if isinstance(lights, vtkLight):
        return [lights]
    return list(lights)


def light_visibility(mesh, lights=(), casters=(), samples=64, cells=False, sun=None,
                     two_sided=False):
    """Shadows as data: how much of each light every point of ``mesh`` sees,
    by ray casting (``vtksoftshadows.vtkLightVisibilityFilter``).

    Parameters
    ----------
    mesh : pyvista.DataSet
        The receiving surface, in world coordinates (its outer surface if it
        is not a ``PolyData``); it casts on itself too. Surfaces receive on
        the side their normals point to (see ``two_sided``).
    lights : pyvista.Plotter, pyvista.Renderer, pyvista.Light or a sequence of lights
        A plotter's or renderer's lights, or the lights themselves, each
        sized as the module sizes lights (``vtkSoftShadowPass.SetRadius``,
        or ``enable_soft_shadows``' ``light_radius``): spheres for spot and
        point lights, cones of directions for directional ones.
    casters : sequence of pyvista.DataSet
        More geometry that casts shadows on ``mesh``.
    samples : int, default: 64
        Rays a light and a point (a square number: stratified).
    cells : bool, default: False
        The arrays on the cells as well, from their centres.
    sun : dict, optional
        The sun over a day: ``latitude`` (degrees), ``day`` (of the year),
        ``step`` (hours, 0.25), ``up`` ((0, 0, 1)), ``north`` ((0, 1, 0)),
        ``radius`` (degrees, 0.27).
    two_sided : bool, default: False
        Each point receives on the side of its surface that faces the light,
        whichever way its normal points (isosurfaces' point inwards).

    Returns
    -------
    pyvista.PolyData
        The surface with ``LightVisibility`` (a component a light) and
        ``Irradiance``, and with ``sun`` ``SunHours`` and ``SunFraction``.

    Raises
    ------
    ValueError
        An unknown ``sun`` key, or neither lights nor a sun.
    RuntimeError
        The filter refused its input (the message says why: a point that is
        not finite, a north along up...).
    """
    light_items = _light_list(lights)
    if not light_items and sun is None:
        raise ValueError("light_visibility: no lights and no sun: give lights, sun or both")
    f = vtkLightVisibilityFilter()
    f.SetInputData(_surface(mesh, "mesh"))
    for caster in casters:
        f.AddCasterData(_surface(caster, "casters"))
    collection = vtkLightCollection()
    for light in light_items:
        collection.AddItem(light)
    f.SetLights(collection)
    f.SetSamples(int(samples))
    f.SetCellVisibility(bool(cells))
    f.SetTwoSided(bool(two_sided))
    if sun is not None:
        unknown = sorted(set(sun) - set(_SUN_KEYS))
        if unknown:
            raise ValueError("light_visibility: unknown sun key(s) %s (known: %s)"
                             % (", ".join(unknown), ", ".join(sorted(_SUN_KEYS))))
        f.SunHoursOn()
        for key, value in sun.items():
            setter = getattr(f, _SUN_KEYS[key])
            setter(*value) if key in ("up", "north") else setter(value)
    errors = []

    @calldata_type(VTK_STRING)
    def refused(caller, event, message):
        errors.append(message)

    # The executive's "returned failure" follows the filter's own reason.
    observers = [(f, f.AddObserver(vtkCommand.ErrorEvent, refused)),
                 (f.GetExecutive(), f.GetExecutive().AddObserver(
                     vtkCommand.ErrorEvent, lambda caller, event: None))]
    try:
        f.Update()
    finally:
        for owner, observer in observers:
            owner.RemoveObserver(observer)
    if errors:
        raise RuntimeError("light_visibility: " + errors[0].strip().splitlines()[-1])
    return pyvista.wrap(f.GetOutput())
