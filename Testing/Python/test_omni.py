"""The `omni` technique: point lights' cube maps (Gerasimov, GPU Gems ch. 12)
softened by a Poisson-disk filter sized from the light's radius. Its
penumbra widens with the occluder's height and it is closer to the
reference than hard shadows; the chapter's 4-tap PCF sits in between."""
import numpy as np

import shadowtest as st

radius = 0.4
widths = []
for height in (0.75, 1.5, 2.25):
    scene = st.ball_scene(height=height, light_radius=radius, technique="omni",
                          light_type="point")
    visibility, _ = st.shadow_only(scene)
    widths.append(st.penumbra_width(scene, visibility))
st.check(widths[0] < widths[1] < widths[2],
         "omni penumbra widens as the ball rises: %s" % np.round(widths, 3).tolist())

scene = st.ball_scene(height=1.5, light_radius=radius, technique="reference",
                      params={"samples": 64}, map_size=512, light_type="point")
reference, _ = st.shadow_only(scene)
mask = st.quality_mask(scene)
errors = {}
for technique in ("hard", "omni:hard", "omni:pcf4", "omni", "contact:pcf", "contact:gaussian",
                  "contact"):
    visibility, _ = st.shadow_only(scene, technique)
    errors[technique] = st.rmse(visibility, reference, mask)
    print("RMSE %-10s %.4f" % (technique, errors[technique]))
st.check(errors["omni:hard"] == errors["hard"] or abs(errors["omni:hard"] - errors["hard"]) < 0.002,
         "omni:hard is hard's cube lookup")
st.check(errors["omni"] < errors["omni:pcf4"] < errors["hard"] + 0.002,
         "poisson beats 4-tap PCF, which is no worse than hard")
st.check(errors["omni"] < 0.6 * errors["hard"], "poisson is well below hard's error")
# The contact technique sizes its kernels from point lights' radii too.
for technique in ("contact:pcf", "contact:gaussian", "contact"):
    st.check(errors[technique] < errors["hard"],
             "%s beats hard under a point light (%.4f < %.4f)"
             % (technique, errors[technique], errors["hard"]))
