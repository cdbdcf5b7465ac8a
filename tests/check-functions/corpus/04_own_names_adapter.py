# An adapter for check-functions.js (docs/students.md, "How the book's data reach your
# code"): give it with --adapter. Define only what your module needs; each function here
# takes the place of the checker's own of the same name.


def setup(module, given, adapter):
    """Called before each case with what the case gives (as dicts and lists):
      given["canvas"]    { width, height, and for drawing functions PutPixel(x, y, color) }
      given["viewport"]  { width, height, d }
      given["scene"]     { spheres: [...], lights: [...], background_color: [r, g, b] }
      given["camera"]    { position, rotation } (chapter 5), given["depth_buffer"] (chapter 12)
    The checker has set the book's names already (Cw, Ch, Vw, Vh, d, scene,
    BACKGROUND_COLOR, PutPixel...), and the demos' (spheres, lights, viewport_size...)
    where your module reads them: set the names of your own here. adapter builds the
    book's records (fields read as sphere.radius or sphere["radius"]):
    adapter.spheres(...), adapter.lights(...), adapter.color(...), adapter.vector(...);
    make your own types here if your code needs them."""
    if "scene" in given:
        module.BACKGROUND = adapter.color(given["scene"].get("background_color", [255, 255, 255]))
        module.LIGHTS[:] = adapter.lights(given["scene"].get("lights", []))  # [:]: the same list, filled in place
        module.SPHERES[:] = adapter.spheres(given["scene"].get("spheres", []))  # [:]: the same list, filled in place
    # your SHADOW_EPSILON (0.001): what does it hold? Set it here if a case gives it.


# Your own types, if your functions take them (each gets the case's JSON value):
# def vector(value):
#     return MyVector(*value)
# def sphere(value):
#     return MySphere(center=value["center"], radius=value["radius"], color=value["color"])
