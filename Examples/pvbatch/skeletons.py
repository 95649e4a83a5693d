"""Hand-made skeletons and poses for CGAL's CC0 meshes (Debian's libcgal-demo, data/meshes),
in each mesh's own coordinates. Joints were placed from cross-sections of the mesh and checked
by rendering which vertices each bone gets (skinning.bone_labels)."""
from skinning import Bone

# CGAL's man: z up, facing -y, his left side at -x.
MAN = [
    Bone("pelvis", None, (-0.02, 0.0, -0.06), (-0.02, 0.0, 0.08)),
    Bone("spine", "pelvis", (-0.02, 0.0, 0.08), (-0.025, 0.0, 0.33)),
    Bone("head", "spine", (-0.027, 0.0, 0.35), (-0.027, -0.02, 0.5), cut_point=(0, 0, 0.36)),
    # The arms hang close to the body: cut from the armpit to the shoulder's top.
    Bone("upper_arm_l", "spine", (-0.14, 0.01, 0.28), (-0.17, 0.035, 0.13),
         cut_normal=(-1, 0, 0.1), cut_point=(-0.12, 0, 0.21)),
    Bone("forearm_l", "upper_arm_l", (-0.17, 0.035, 0.13), (-0.187, 0.04, 0.0)),
    Bone("hand_l", "forearm_l", (-0.187, 0.04, 0.0), (-0.187, 0.035, -0.065)),
    Bone("upper_arm_r", "spine", (0.095, -0.03, 0.28), (0.12, -0.06, 0.13),
         cut_normal=(1, 0, 0), cut_point=(0.076, 0, 0.21)),
    Bone("forearm_r", "upper_arm_r", (0.12, -0.06, 0.13), (0.125, -0.09, 0.02)),
    Bone("hand_r", "forearm_r", (0.125, -0.09, 0.02), (0.125, -0.10, -0.02)),
    Bone("thigh_l", "pelvis", (-0.07, 0.02, -0.04), (-0.12, 0.07, -0.25)),
    Bone("shin_l", "thigh_l", (-0.12, 0.07, -0.25), (-0.14, 0.11, -0.44)),
    Bone("foot_l", "shin_l", (-0.14, 0.11, -0.44), (-0.17, 0.04, -0.49)),
    Bone("thigh_r", "pelvis", (0.05, -0.04, -0.04), (0.125, -0.045, -0.25)),
    Bone("shin_r", "thigh_r", (0.125, -0.045, -0.25), (0.175, -0.05, -0.44)),
    Bone("foot_r", "shin_r", (0.175, -0.05, -0.44), (0.19, -0.13, -0.48)),
]

X, Y, Z = (1, 0, 0), (0, 1, 0), (0, 0, 1)

MAN_POSES = {
    # Arms raised sideways above the shoulders, legs closer together, head turned.
    "arms_up": {"upper_arm_l": (Y, 80), "forearm_l": (Y, 25), "upper_arm_r": (Y, -80),
                "forearm_r": (Y, -25), "thigh_l": (Y, -8), "thigh_r": (Y, -8), "head": (Z, 40)},
    # Torso turned, one arm forward and the other back, a step with a bent knee, head turned.
    "turned_step": {"spine": (Z, 40), "upper_arm_l": (X, -75), "forearm_l": (X, -30),
                    "upper_arm_r": (X, 30), "thigh_r": (X, -45), "shin_r": (X, 70),
                    "thigh_l": (X, 10), "head": (Z, -45)},
    # Sitting on a (missing) chair: thighs forward, knees bent, arms forward, head turned.
    "sit": {"thigh_l": (X, -85), "thigh_r": (X, -85), "shin_l": (X, 85), "shin_r": (X, 85),
            "upper_arm_l": (X, -30), "upper_arm_r": (X, -30), "head": (Z, 30)},
    # Legs wide apart, torso leaning to his left, the left arm held out from the thigh,
    # the right elbow bent, the hand in front of the belly.
    "legs_apart": {"thigh_l": (Y, 22), "thigh_r": (Y, -22), "shin_l": (Y, -10), "shin_r": (Y, 10),
                   "spine": (Y, -10), "head": (Y, 10), "upper_arm_l": (Y, 25),
                   "upper_arm_r": (X, -15), "forearm_r": (X, -80)},
    # Bowing: bent forward at the waist, one arm forward, the other out, head turned.
    "bow": {"spine": (X, 60), "upper_arm_l": (X, -40), "upper_arm_r": (Y, -40), "head": (Z, -40)},
    # Crouching: bent forward at the waist, knees bent, arms reaching forward.
    "crouch": {"spine": (X, 35), "upper_arm_l": (X, -60), "upper_arm_r": (X, -60),
               "thigh_l": (X, -60), "thigh_r": (X, -60), "shin_l": (X, 100), "shin_r": (X, 100)},
}


def quadruped_legs(body, legs):
    """Upper and lower leg bones of a four-legged animal: `legs` maps a leg name (fl, fr, hl,
    hr: front/hind, left/right) to its hip or shoulder joint, knee, hoof and cut height (the
    leg is cut from the body by a horizontal plane there: y up on every animal here)."""
    bones = []
    for name, (hip, knee, hoof, height) in legs.items():
        bones.append(Bone("upper_" + name, body, hip, knee, cut_normal=(0, -1, 0),
                          cut_point=(0, height, 0)))
        bones.append(Bone("lower_" + name, "upper_" + name, knee, hoof))
    return bones


# CGAL's cow: y up, facing +x, her left side at -z. The hind legs are joined by the udder
# above y = -0.17.
COW = [
    Bone("body", None, (-0.1, 0.05, 0.0), (0.1, 0.05, 0.0)),
    Bone("head", "body", (0.2, 0.12, 0.0), (0.45, 0.15, 0.0), cut_normal=X, cut_point=(0.24, 0, 0)),
    # The tail hangs against the rump: no plane separates them.
    Bone("tail", "body", (-0.44, 0.17, 0.0), (-0.49, -0.14, 0.0), reach=0.36),
] + quadruped_legs("body", {
    "fl": ((0.09, -0.06, -0.089), (0.101, -0.218, -0.08), (0.132, -0.295, -0.092), -0.13),
    "fr": ((0.09, -0.06, 0.089), (0.101, -0.218, 0.08), (0.132, -0.295, 0.092), -0.13),
    "hl": ((-0.35, -0.07, -0.098), (-0.367, -0.22, -0.098), (-0.37, -0.30, -0.098), -0.17),
    "hr": ((-0.35, -0.07, 0.098), (-0.367, -0.22, 0.098), (-0.37, -0.30, 0.098), -0.17),
})

COW_POSES = {
    # Walking: diagonal legs forward and back, head turned and lowered, tail swung.
    "walk": {"upper_fl": (Z, 30), "lower_fl": (Z, -35), "upper_hr": (Z, 25), "upper_fr": (Z, -25),
             "upper_hl": (Z, -30), "lower_hl": (Z, 25), "head": (Y, 35), "tail": (X, 40)},
    # Lying down: legs folded under the body, head turned towards the flank.
    "lie": {"head": (Y, 70), "upper_fl": (Z, -40), "lower_fl": (Z, 65), "upper_fr": (Z, -40),
            "lower_fr": (Z, 65), "upper_hl": (Z, 35), "lower_hl": (Z, -55), "upper_hr": (Z, 35),
            "lower_hr": (Z, -55)},
    # Grazing: head down and to the other side, front legs apart, tail swung the other way.
    "graze": {"head": ((0, 0.6, 1), -40), "upper_fl": (X, -12), "upper_fr": (X, 12),
              "upper_hl": (Z, 15), "upper_hr": (Z, 15), "tail": (X, -50)},
}

# CGAL's bull, charging: y up, facing -x, his left side at +z; right foreleg thrown out.
BULL = [
    Bone("body", None, (0.1, 0.05, 0.0), (-0.1, 0.05, 0.0)),
    # Behind the horns, in front of the brisket.
    Bone("head", "body", (-0.25, 0.08, 0.03), (-0.48, 0.05, 0.1), cut_normal=(-1, 0.6, 0),
         cut_point=(-0.25, 0.05, 0)),
] + quadruped_legs("body", {
    "fl": ((-0.2, -0.09, 0.013), (-0.323, -0.251, -0.045), (-0.409, -0.323, -0.071), -0.16),
    "fr": ((-0.2, -0.1, -0.2), (-0.251, -0.232, -0.329), (-0.297, -0.299, -0.361), -0.16),
    "hl": ((0.43, -0.09, 0.08), (0.396, -0.251, 0.106), (0.324, -0.332, 0.138), -0.16),
    "hr": ((0.33, -0.09, -0.15), (0.257, -0.228, -0.202), (0.192, -0.292, -0.221), -0.16),
})

BULL_POSES = {
    # Standing square: legs brought under the body, head turned and raised.
    # (Facing -x: a positive turn about z swings a leg backwards.)
    "stand": {"upper_fl": (Z, 35), "upper_fr": (X, -30), "upper_hl": (Z, -10),
              "upper_hr": (Z, 20), "head": ((0, 1, -0.4), 35)},
    # The charge reversed: legs swapped forward and back, head turned the other way and down.
    "gallop": {"upper_fl": (Z, 50), "lower_fl": (Z, -30), "upper_hl": (Z, 25),
               "upper_hr": (Z, -25), "head": ((0, 1, 0.6), -35)},
}

# CGAL's camel: y up, facing +z, its left side at +x; long neck down then up to the head.
CAMEL = [
    Bone("body", None, (0.0, 0.1, -0.2), (0.0, 0.1, 0.0)),
    Bone("neck", "body", (0.0, 0.2, 0.13), (0.0, 0.17, 0.3), cut_normal=Z, cut_point=(0, 0, 0.17)),
    Bone("head", "neck", (0.0, 0.3, 0.3), (0.0, 0.42, 0.5), cut_normal=Y, cut_point=(0, 0.33, 0)),
] + quadruped_legs("body", {
    "fl": ((0.05, 0.0, 0.04), (0.025, -0.275, 0.02), (0.07, -0.477, 0.085), -0.07),
    "fr": ((-0.05, 0.0, 0.04), (-0.025, -0.275, 0.02), (-0.07, -0.477, 0.085), -0.07),
    "hl": ((0.05, 0.0, -0.4), (0.035, -0.27, -0.46), (0.081, -0.477, -0.382), -0.07),
    "hr": ((-0.05, 0.0, -0.4), (-0.035, -0.27, -0.46), (-0.081, -0.477, -0.382), -0.07),
})

CAMEL_POSES = {
    # Walking (a camel paces: both legs of one side together), head turned.
    "pace": {"upper_fl": (X, -25), "lower_fl": (X, 30), "upper_hl": (X, -20),
             "upper_fr": (X, 20), "upper_hr": (X, 25), "lower_hr": (X, -20), "head": (Y, 40)},
    # Neck lowered and turned, front legs splayed, hind legs apart.
    "drink": {"neck": (X, -35), "head": (Y, -35), "upper_fl": (Z, 15),
              "upper_fr": (Z, -15), "upper_hl": (Z, 10), "upper_hr": (Z, -10)},
}

# CGAL's teddy bear, sitting: y up, facing +z, its left side at +x; arms and legs held out.
BEAR = [
    Bone("body", None, (0.0, -0.3, 0.0), (0.0, 0.2, 0.0)),
    Bone("head", "body", (0.0, 0.42, 0.0), (0.0, 0.85, 0.0), cut_normal=Y, cut_point=(0, 0.45, 0)),
    Bone("arm_l", "body", (0.33, 0.18, 0.03), (0.66, 0.18, 0.07), cut_normal=(1, 0.5, 0),
         cut_point=(0.38, 0.12, 0)),
    Bone("arm_r", "body", (-0.33, 0.18, 0.03), (-0.66, 0.18, 0.07), cut_normal=(-1, 0.5, 0),
         cut_point=(-0.38, 0.12, 0)),
    Bone("leg_l", "body", (0.3, -0.45, 0.0), (0.62, -0.58, 0.08), cut_normal=(1, -0.3, 0),
         cut_point=(0.3, -0.45, 0)),
    Bone("leg_r", "body", (-0.3, -0.45, 0.0), (-0.62, -0.58, 0.08), cut_normal=(-1, -0.3, 0),
         cut_point=(-0.3, -0.45, 0)),
]

BEAR_POSES = {
    # One arm up, the other down, head turned, one leg lifted forward.
    "wave": {"arm_l": (Z, 60), "arm_r": (Z, 40), "head": (Y, 40), "leg_l": (X, -40)},
    # Arms forward, legs together in front, head tilted.
    "hug": {"arm_l": (Y, -50), "arm_r": (Y, 50), "leg_l": (Y, -35), "leg_r": (Y, 35),
            "head": ((0, 0.3, 1), 25)},
}
