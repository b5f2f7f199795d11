"""Writes the robot's limbs and its walk (thesis Ch. 3.3, figs. 3.3.2-3.3.3): one step forward.

The robot is drawn face-on in the plane x = 0 (y forward, z up), in its own coordinates: the walk
(walk.dat, the robot's MOVE) carries it. Every limb is RIGID in robot.scn, so its two key drawings
must be congruent: each is drawn here from one shape turned to the limb's angle in each key.

- The standing leg (right) is straight, 3.8 long, and leans 14.48 degrees forward
  in KEY1 (asin 0.25), as far back in KEY2, so the hip travels an arc of radius 3.8 about the ankle
  and moves 1.9 forward. walk.dat holds that arc as 7 control points: the hip's path. Its ankle is
  one world point in both keys (0.95 ahead of the hip at the start).
- The swinging leg (left) is bent at the knee in both keys, its foot on the ground 0.32 behind the
  hip in KEY1 (thigh 8 degrees forward, calf 19.3 back) and 2.18 ahead of where the hip started in
  KEY2 (thigh 17.4 forward, calf 10.3 back). Both its limbs turn at one rate while the hip rises and
  falls 0.12 on its arc, so the foot clears the ground by up to 0.11 between the keys and touches
  it only at them (a larger lift needs a knee that bends and straightens between the keys: a third
  key frame, which APCS, like the thesis, does not have).
- The arms swing against the legs, 25 degrees each way; the palm and finger turn with their arm.
- The soles stay level.

Run in data/robot: python3 make_robot.py  (the files are rewritten; the same bytes each time).
"""
import math

THIGH, CALF = 2.0, 1.8
LEG = THIGH + CALF
HIP = (0.0, 4.0)
SHOULDER = (0.0, 6.7)
ARM = 1.7
STEP = math.asin(0.25)  # the standing leg's angle from upright in each key
GROUND_ANKLE = HIP[1] - LEG * math.cos(STEP)  # the ankles' height when a sole is on the ground
TRAVEL = 2 * LEG * math.sin(STEP)  # the hip's way forward: 1.9
# The swinging leg's thigh and calf angles from upright (forward positive), in KEY1 and KEY2.
SWING_THIGH = (math.radians(8.0), math.radians(17.4))
ARM_SWING = math.radians(25.0)
# The palm and the finger in the arm's own axes (along the arm, across it), from the wrist.
PALM = [(0.0, 0.0), (0.2574, 0.0786), (0.4500, 0.0000), (0.1759, -0.2144), (0.0, 0.0)]
FINGER = [(0.4500, 0.0000), (0.7263, 0.1169)]
SOLE = [(0.0, 0.0), (-0.25, -0.3), (0.65, -0.3), (0.0, 0.0)]


def along(start, angle, length):
    """The point `length` from `start` in the direction `angle` from straight down (forward +)."""
    return (start[0] + length * math.sin(angle), start[1] - length * math.cos(angle))


def in_arm_axes(wrist, angle, offsets):
    down = (math.sin(angle), -math.cos(angle))
    across = (math.cos(angle), math.sin(angle))
    return [(wrist[0] + a * down[0] + c * across[0], wrist[1] + a * down[1] + c * across[1]) for a, c in offsets]


def calf_reaching_ground(thigh_angle):
    """The calf angle (at or behind the thigh's) that puts the ankle on the ground, hip at HIP."""
    return -math.acos((HIP[1] - GROUND_ANKLE - THIGH * math.cos(thigh_angle)) / CALF)


def write(name, heading, points):
    with open(name, "w") as out:
        out.write(heading)
        for y, z in points:
            out.write(f"0 {y:.6f} {z:.6f}\n".replace("-0.000000", "0.000000"))


def leg(side, key, thigh_angle, calf_angle):
    hip = HIP
    knee = along(hip, thigh_angle, THIGH)
    ankle = along(knee, calf_angle, CALF)
    name = "left" if side == "l" else "right"
    write(f"thigh-{side}{key}.dat", f"; Thigh ({name}) in KEY{key}: hip, knee.\n", [hip, knee])
    write(f"calf-{side}{key}.dat", f"; Calf ({name}) in KEY{key}: knee, ankle.\n", [knee, ankle])
    write(f"sole-{side}{key}.dat", f"; Sole ({name}) in KEY{key}: ankle, heel, toe, ankle.\n",
          [(ankle[0] + y, ankle[1] + z) for y, z in SOLE])


def hand(side, key, angle):
    name = "left" if side == "l" else "right"
    wrist = along(SHOULDER, angle, ARM)
    write(f"arm-{side}{key}.dat", f"; Arm ({name}) in KEY{key}: shoulder, wrist (point B of fig. 3.3.3).\n",
          [SHOULDER, wrist])
    write(f"palm-{side}{key}.dat", f"; Palm ({name}) in KEY{key}: wrist, knuckle at point 3.\n",
          in_arm_axes(wrist, angle, PALM))
    write(f"finger-{side}{key}.dat", f"; Finger ({name}) in KEY{key}: knuckle, tip.\n",
          in_arm_axes(wrist, angle, FINGER))


def main():
    # The standing leg, straight. In KEY2 the robot has walked TRAVEL: its own coordinates (the hip
    # stays at HIP in them) are TRAVEL behind the world's, so the still ankle is TRAVEL further back.
    leg("r", 1, STEP, STEP)
    leg("r", 2, -STEP, -STEP)
    thigh1, thigh2 = SWING_THIGH
    leg("l", 1, thigh1, calf_reaching_ground(thigh1))
    leg("l", 2, thigh2, calf_reaching_ground(thigh2))
    hand("l", 1, ARM_SWING)
    hand("l", 2, -ARM_SWING)
    hand("r", 1, -ARM_SWING)
    hand("r", 2, ARM_SWING)
    ankle = along(HIP, STEP, LEG)
    arc = [(ankle[0] - LEG * math.sin(STEP - 2 * STEP * k / 6), ankle[1] + LEG * math.cos(STEP - 2 * STEP * k / 6))
           for k in range(7)]
    write("walk.dat", "; The robot's walk: its hip's arc about the standing ankle, radius 3.8, one step of 1.9\n"
          "; (make_robot.py). The standing leg, hung from the hip, turns by the same law: the foot stays.\n", arc)


main()
