# cycles_render.py: renders cycles_export's scene (bench/cycles_compare) with Blender's
# Cycles, the way trace --sampling montecarlo --bounces 1 renders it: the OBJ facets with
# one Lambertian (Diffuse BSDF) material per sigchain material and .ems curve (the
# reflectance of three band-centre spectral samples as R, G, B), a sun lamp (a point
# sun: angle 0) with the ground's direct irradiance, a uniform sky of the .rad sky's
# horizontal irradiance above the horizon and black below (trace --background none),
# the .adv's frame camera; Cycles on the CPU, one bounce (max and diffuse bounces 1,
# no glossy, transmission, volume or transparency bounces, no caustics, no clamping),
# a 1-pixel box filter, no adaptive sampling, no denoising, a fixed seed.
#
#   blender -b -noaudio --python-exit-code 1 --python cycles_render.py -- \
#       DIR SAMPLES SEED THREADS OUT.raw [once]
#
# DIR holds scene.obj and scene.txt (cycles_export). OUT.raw: the image as float32,
# three planes (R, G, B = the cube bands named in scene.txt), rows top to bottom, in
# uW cm-2 sr-1 um-1. Prints, on lines starting "cycles:", the epoch time at the end of
# the first render (the set-up included: Blender's start, the import, Cycles' scene
# sync and BVH build), and the seconds of a second, identical render with persistent
# data (the BVH kept: the set-up excluded, path tracing alone); with `once`, no second
# render (the references).
import array
import sys
import time

import bpy
from mathutils import Matrix, Vector

argv = sys.argv[sys.argv.index("--") + 1:]
folder, samples, seed, threads, out_path = argv[0], int(argv[1]), int(argv[2]), int(argv[3]), argv[4]
once = argv[5:] == ["once"]


def read_params(path):
    params, materials = {}, {}
    with open(path) as f:
        for line in f:
            words = line.split()
            if not words:
                continue
            if words[0] == "material":
                materials[words[1]] = [float(v) for v in words[2:5]]
            else:
                params[words[0]] = [float(v) for v in words[1:]]
    return params, materials


params, materials = read_params(folder + "/scene.txt")

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene

# The geometry, already z up in the scene frame (metres).
bpy.ops.wm.obj_import(filepath=folder + "/scene.obj", forward_axis="Y", up_axis="Z")


def diffuse(name, rgb):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nodes = m.node_tree.nodes
    nodes.clear()
    bsdf = nodes.new("ShaderNodeBsdfDiffuse")
    bsdf.inputs["Color"].default_value = (rgb[0], rgb[1], rgb[2], 1.0)
    bsdf.inputs["Roughness"].default_value = 0.0  # Lambert
    out = nodes.new("ShaderNodeOutputMaterial")
    m.node_tree.links.new(bsdf.outputs["BSDF"], out.inputs["Surface"])
    return m


made = {key: diffuse("sigchain_" + key, rgb) for key, rgb in materials.items()}
for obj in scene.objects:
    if obj.type != "MESH":
        continue
    for slot in obj.material_slots:
        key = slot.material.name.split(".")[0] if slot.material else None
        if key not in made:
            raise SystemExit("cycles_render: material %r not in scene.txt" % key)
        slot.material = made[key]

# The sun: a distant lamp whose strength is irradiance normal to it (W m-2 in Blender,
# here uW cm-2 um-1; a Lambertian facet then has radiance rho E cos / pi).
sun_e = params["sun_irradiance"]
sun_data = bpy.data.lights.new("sun", "SUN")
sun_data.energy = max(sun_e)
sun_data.color = tuple(e / max(sun_e) for e in sun_e)
sun_data.angle = 0.0
sun_data.cycles.cast_shadow = True
sun = bpy.data.objects.new("sun", sun_data)
sun.rotation_euler = Vector(params["sun_direction"]).to_track_quat("Z", "Y").to_euler()
scene.collection.objects.link(sun)

# The sky: uniform radiance above the horizon, black below (a world direction's z is
# the Generated coordinate's).
world = bpy.data.worlds.new("sky")
world.use_nodes = True
nodes, links = world.node_tree.nodes, world.node_tree.links
nodes.clear()
coords = nodes.new("ShaderNodeTexCoord")
split = nodes.new("ShaderNodeSeparateXYZ")
above = nodes.new("ShaderNodeMath")
above.operation = "GREATER_THAN"
above.inputs[1].default_value = 0.0
mix = nodes.new("ShaderNodeMixRGB")
mix.inputs["Color1"].default_value = (0, 0, 0, 1)
sky = params["sky_radiance"]
mix.inputs["Color2"].default_value = (sky[0], sky[1], sky[2], 1)
background = nodes.new("ShaderNodeBackground")
background.inputs["Strength"].default_value = 1.0
world_out = nodes.new("ShaderNodeOutputWorld")
links.new(coords.outputs["Generated"], split.inputs["Vector"])
links.new(split.outputs["Z"], above.inputs[0])
links.new(above.outputs["Value"], mix.inputs["Fac"])
links.new(mix.outputs["Color"], background.inputs["Color"])
links.new(background.outputs["Background"], world_out.inputs["Surface"])
scene.world = world

# The .adv's frame camera: image x along `right`, image up = -`down`, looking along
# `forward` (Blender's camera looks down its -Z, its +Y up).
right, down, forward = (Vector(params[k]) for k in ("camera_right", "camera_down", "camera_forward"))
cam_data = bpy.data.cameras.new("camera")
cam_data.sensor_fit = "HORIZONTAL"
cam_data.sensor_width = params["columns"][0] * params["pixel_pitch_mm"][0]
cam_data.lens = params["focal_length_mm"][0]
cam_data.clip_start = 0.01
cam_data.clip_end = 1.0e6
cam = bpy.data.objects.new("camera", cam_data)
rotation = Matrix((right, -down, -forward)).transposed()
cam.matrix_world = Matrix.Translation(Vector(params["camera_position"])) @ rotation.to_4x4()
scene.collection.objects.link(cam)
scene.camera = cam

render = scene.render
render.engine = "CYCLES"
render.resolution_x = int(params["columns"][0])
render.resolution_y = int(params["rows"][0])
render.resolution_percentage = 100
render.pixel_aspect_x = render.pixel_aspect_y = 1
render.threads_mode = "FIXED"
render.threads = threads
render.use_persistent_data = True
render.image_settings.file_format = "OPEN_EXR"
render.image_settings.color_depth = "32"
render.image_settings.color_mode = "RGB"
render.film_transparent = False
scene.view_settings.view_transform = "Standard"
c = scene.cycles
c.device = "CPU"
c.samples = samples
c.use_adaptive_sampling = False
c.use_denoising = False
c.seed = seed
c.use_animated_seed = False
c.max_bounces = 1
c.diffuse_bounces = 1
c.glossy_bounces = 0
c.transmission_bounces = 0
c.volume_bounces = 0
c.transparent_max_bounces = 0
c.caustics_reflective = False
c.caustics_refractive = False
c.sample_clamp_direct = 0.0
c.sample_clamp_indirect = 0.0
c.pixel_filter_type = "BOX"
c.filter_width = 1.0
c.use_auto_tile = False
scene.view_layers[0].cycles.denoising_store_passes = False

exr = out_path + ".exr"
render.filepath = exr
bpy.ops.render.render(write_still=True)
print("cycles: first render ended at %.6f" % time.time(), flush=True)
if not once:
    t0 = time.perf_counter()
    bpy.ops.render.render(write_still=False)
    print("cycles: second render %.6f s" % (time.perf_counter() - t0), flush=True)

image = bpy.data.images.load(exr)
w, h = image.size
pixels = array.array("f", bytes(4 * w * h * image.channels))
image.pixels.foreach_get(pixels)
nc = image.channels
planes = array.array("f")
for ch in range(3):
    for row in range(h - 1, -1, -1):  # Blender's rows run bottom to top
        base = row * w * nc
        planes.extend(pixels[base + col * nc + ch] for col in range(w))
with open(out_path, "wb") as f:
    planes.tofile(f)
