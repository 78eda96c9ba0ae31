"""Blind held-out command sentences written on 2026-11-29, third batch (``--set heldout20``).

Written at 14:25 UTC by a helper that read nothing of the repository (only the scenes' object lists
in the robot's frame, the goal words and a brief of eight voices: a robotics engineer's jargon, a
radio operator, a British speaker's idioms, objects named by comparison or rank only, negation and
exclusion, a purpose instead of an instruction, a typo-ridden phone message, multi-step tasks mixed
with requests to decline), added verbatim. Measured with ``--plans`` at d15e3d9 (the session's
start, nothing in it tuned for these): 26/64. Then read, and its failures' classes fixed (radio
procedure, a thing singled out before it is acted on, a purpose before the request, an engineer's
names for the primitives and axes, chat shorthand, "the smaller of the two" in a scene of two):
61/64, no longer blind (the three left: "the thing closest to you" is read along the robot's forward axis, not as a
distance from it; a lift of a box the hand cannot hold is planned and then declined by the grasp; a
placing undone by "put it back where it was").
"""
from __future__ import annotations

HELDOUT20: list[tuple[str, str, str]] = [
    # voice 1: robotics engineer
    ("kitchen", "Execute a pick on the mug, place pose inside the bowl, then return to nominal.", "in mug bowl; home"),
    ("pantry", "Translate the foam brick 4 cm in -y; keep the current yaw.", "moved foam_brick right 0.04"),
    ("mugbowl", "Grasp target is the mug. Place pose on the +y side of the bowl, clear of the rim, then home the arm.", "left mug bowl; home"),
    ("fruitcans", "Pick the strawberry and put the place pose at a -x offset from the banana, so it lands directly in front of it.", "front strawberry banana"),
    ("textkitchen", "Of the two soda cans, take the one with the smaller y coordinate, drop it into the bowl, then send the end effector back to its home config.", "in soda_can@right bowl; home"),
    ("textblocks", "Pick the green cube; place pose roughly 8 cm in +x from the red cube.", "behind cube@green cube@red"),
    ("scan45", "The small white object is stacked on the big white one. Execute a pick and place it on the table surface wherever there's clearance.", "table small_white_object"),
    ("scan55", "Blue box exceeds the gripper aperture, so no grasp: push it 5 cm along +x.", "moved blue_box forward 0.05"),
    # voice 2: walkie-talkie / radio
    ("kitchen", "Robot, this is Sam, over. Mug goes to the left of the cracker box. How copy? Over.", "left mug cracker_box"),
    ("pantry", "Base to robot, come in. Take the Rubik's cube and set it down behind the mustard. Over and out.", "behind rubiks_cube mustard_bottle"),
    ("mugbowl", "Robot, Sam again. Slide the bowl back toward you, roughly four inches. Acknowledge, over.", "moved bowl back 0.1016"),
    ("fruitcans", "Control to robot: swap the soup can and the Rubik's cube. Copy? Over.", "swapped tomato_soup_can rubiks_cube"),
    ("textkitchen", "Robot, this is Dana. Get the cereal box out of the way, then stand by at home position. Roger, out.", "aside cereal_box; home"),
    ("textblocks", "Robot, do you read me? Put the green cube between the red cube and the blue cube. Over.", "between cube@green cube@red cube@blue"),
    ("scan45", "Robot, Jo here, over. Lift the tall white can and hold it. Copy?", "lift left_tall_white_can"),
    ("scan55", "Robot, this is Sam. Pick up the red box and hold it there. Over.", "refuse"),
    # voice 3: British, idioms
    ("kitchen", "Be a love and shove the cracker box over a tad to the left, three centimetres or so. Ta.", "moved cracker_box left 0.03"),
    ("pantry", "Would you pop the marker next to the tin of potted meat? Cheers.", "next large_marker potted_meat_can"),
    ("mugbowl", "Could you nudge the mug forward ever so slightly? A couple of centimetres, no more.", "moved mug forward 0.02"),
    ("fruitcans", "Pop the strawberry in the bowl, there's a good chap.", "in strawberry bowl"),
    ("textkitchen", "Be a dear and pop the left-hand can of pop just to the right of the cereal box, cheers.", "right soda_can@left cereal_box"),
    ("textblocks", "Just nudge the red block a smidge to the right, would you? Two centimetres should do it.", "moved cube@red right 0.02"),
    ("scan45", "That red can's a bit of a lump to lift, so just shove it back towards me, about 5 centimetres, ta.", "moved red_can back 0.05"),
    ("scan55", "Fancy popping the small white thing into the white bowl? Lovely, cheers.", "in small_white_object white_bowl"),
    # voice 4: comparison / rank only
    ("kitchen", "Take the tallest item and put it right beside whatever's furthest to the right.", "next cracker_box mug"),
    ("pantry", "Move the rightmost thing so it ends up to the left of the leftmost thing.", "left large_marker mustard_bottle"),
    ("mugbowl", "Put the smaller of the two into the bigger one.", "in mug bowl"),
    ("fruitcans", "Whatever's furthest away from you, set it to the right of the thing closest to you.", "right strawberry rubiks_cube"),
    ("textkitchen", "The second object from the left should go in front of the rightmost one.", "front soda_can@right bowl"),
    ("textblocks", "The cube nearest to you goes on the plate, then the cube farthest from you goes next to the plate.", "on cube@red plate; next cube@green plate"),
    ("scan45", "Of the two white cans, lift the shorter one.", "lift right_white_can"),
    ("scan55", "Among the yellow objects, take the one furthest from you and push it 5 cm left.", "moved second_from_left_yellow_object left 0.05"),
    # voice 5: negation and exclusion
    ("kitchen", "Leave the mug alone, it's the bowl I'm after: push it 5 cm forward, away from me.", "moved bowl forward 0.05"),
    ("pantry", "Don't lift the mustard bottle; slide it 3 cm to the right instead.", "moved mustard_bottle right 0.03"),
    ("mugbowl", "Leave the bowl be. Only the mug, and just lift it up, nothing more.", "lift mug"),
    ("fruitcans", "Nothing else moves apart from the soup can: put it beside the potted meat.", "next tomato_soup_can potted_meat_can"),
    ("textkitchen", "Not the right soda can, the other one. Put it behind the bowl.", "behind soda_can@left bowl"),
    ("textblocks", "Don't touch the red or the blue cube. Only the green one: set it to the right of the plate.", "right cube@green plate"),
    ("scan45", "Leave the red can and the white cans be; it's the red box I mean. Push it, don't lift it, 5 cm to the right.", "moved red_box right 0.05"),
    ("scan55", "Not the white box, the white bowl: push that 5 cm to the left.", "moved white_bowl left 0.05"),
    # voice 6: purpose instead of instruction
    ("kitchen", "I'm heating up soup later, so the soup can should be sitting right next to the bowl.", "next tomato_soup_can bowl"),
    ("pantry", "I'm about to write a shopping list, so I'd like the marker just in front of the foam brick where I can reach it.", "front large_marker foam_brick"),
    ("mugbowl", "I want a photo of the bowl with nothing else in the shot, so the mug has to go out of the way.", "aside mug"),
    ("fruitcans", "I'm going to lay my tablet down right in front of you, so the Rubik's cube can't stay where it is.", "aside rubiks_cube"),
    ("textkitchen", "I'm starving, I need the cereal box opened so I can have breakfast.", "refuse"),
    ("textblocks", "My daughter's learning colours and I want to quiz her on blue, so the blue cube should be sitting on the plate.", "on cube@blue plate"),
    ("scan45", "I want to read the label on the flat white box, so the right white can sitting on top of it has to go somewhere else.", "aside right_white_can"),
    ("scan55", "I'm about to set a coffee down where the tall white can is, so clear it away for me.", "aside tall_white_can"),
    # voice 7: short, typo-ridden phone message
    ("kitchen", "soup cn nxt 2 banana thx", "next tomato_soup_can banana"),
    ("pantry", "brick on rubix cube pls", "on foam_brick rubiks_cube"),
    ("mugbowl", "bowl 5cm rite plz", "moved bowl right 0.05"),
    ("fruitcans", "pls pour soup in2 bowl", "refuse"),
    ("textkitchen", "cereal bx 5cm fwd", "moved cereal_box forward 0.05"),
    ("textblocks", "red cube ontop blu 1 thx", "on cube@red cube@blue"),
    ("scan45", "tall wht can 2 teh left 5cm", "moved left_tall_white_can left 0.05"),
    ("scan55", "tall wht can in white bowl plz", "in tall_white_can white_bowl"),
    # voice 8: mixed multi-step, plus requests to decline
    ("kitchen", "First get the soup can out of the way, then put the mug where the soup can was, and once that's done, head home.", "aside tomato_soup_can; spot mug tomato_soup_can; home"),
    ("pantry", "Grab the scissors and put them next to the marker.", "refuse"),
    ("mugbowl", "Put the mug in front of the bowl and after that put it back where it was.", "front mug bowl; at mug"),
    ("fruitcans", "Slide the potted meat tin 10 cm back toward me, then put the strawberry where the tin used to be.", "moved potted_meat_can back 0.1; spot strawberry potted_meat_can"),
    ("textkitchen", "Drop the soda can into the bowl for me.", "refuse"),
    ("textblocks", "Swap the red and green cubes, and once that's done put the blue one in front of the plate.", "swapped cube@red cube@green; front cube@blue plate"),
    ("scan45", "Take the small white object off the big white object and set it beside the tall white can, then go home.", "next small_white_object left_tall_white_can; home"),
    ("scan55", "Slide the yellow object 5 cm to the left.", "refuse"),
]
