"""Blind held-out command sentences written on 2026-11-26, third batch (``--set heldout16``).

Written by someone who never read the planner, its tests, the other sets or any file of the
repository (only the scenes' object lists and the goal words), added verbatim. It was kept sealed
(shown to nobody working on the planner) from its writing until the end of that session's planner
work, and measured both at the start (9c57379) and at the end.
"""

from __future__ import annotations

# Written on 2026-11-26 (15:33 UTC) as six kinds of people talk: a terse warehouse supervisor, a voice-assistant
# user (speech-to-text), a parent tidying with a child, an engineer with mixed units, someone who corrects
# themselves mid-sentence, someone who uses comparisons and conditions.
HELDOUT16: list[tuple[str, str, str]] = [
    # warehouse / logistics supervisor, terse
    ("kitchen", "Soup can next to the mug.", "next soup_can mug"),
    ("pantry", "Rubik's cube behind the mustard.", "behind rubiks_cube mustard_bottle"),
    ("mugbowl", "Mug in bowl. Then home.", "in mug bowl; home"),
    ("fruitcans", "All cans next to the bowl.", "next meat_can bowl; next soup_can bowl"),
    ("textkitchen", "Soda can into the bowl.", "refuse"),
    ("textblocks", "Red cube on plate. Green, same.", "on cube@right plate; on cube@left plate"),
    ("scan45", "Red can. 10 cm right.", "moved red_can right 0.1"),
    ("scan55", "Tall white can into the white bowl. Go.", "in tall_white_can white_bowl"),
    # voice-assistant user (speech-to-text)
    ("kitchen", "hey robot put the tomato soup can next to the crack her box", "next soup_can cracker_box"),
    ("pantry", "okay robot pick up the scissors and put them by the marker", "refuse"),
    ("mugbowl", "grab the mug and um put it in front of the bowl please", "front mug bowl"),
    ("fruitcans", "put the straw berry in the bowl", "in strawberry bowl"),
    ("textkitchen", "push the cereal books forward ten centimeters", "moved cereal_box forward 0.1"),
    ("textblocks", "put the read cube in front of the plate", "front cube@right plate"),
    ("scan45", "pick up the tall white can and then put it back down where it was", "at tall_white_can"),
    ("scan55", "put the big white thing in front of the orange cylinder thank you", "front big_white_object orange_cylinder"),
    # parent tidying up with a child
    ("kitchen", "Okay robot, can you swap the banana and the mug? She wants the banana closer to her.", "swapped banana mug"),
    ("pantry", "Could you help us tidy? Put the big marker next to the mustard so we don't lose it.", "next marker mustard_bottle"),
    ("mugbowl", "Look sweetie, the robot can pick up the mug! Can you lift it up for us?", "lift mug"),
    ("fruitcans", "Can you put the Rubik's cube next to the soup can, honey wants them together. Thank you!", "next rubiks_cube soup_can"),
    ("textkitchen", "Could you move the cereal box over next to the bowl please? The little one keeps grabbing it.", "next cereal_box bowl"),
    ("textblocks", "can you put the cube on the plate for us?", "refuse"),
    ("scan45", "Can you put the tall white can to the left of the red can? We're lining them up.", "left tall_white_can red_can"),
    ("scan55", "Let's clean up, could you put the smallest white piece in the white bowl and then go back home?", "in small_white_object white_bowl; home"),
    # scientist / engineer, precise mixed units
    ("kitchen", "Place the banana exactly 40 mm from the orange, long axis parallel to the table edge.", "refuse"),
    ("pantry", "Place the foam brick at the midpoint between the mustard bottle and the Rubik's cube, +/- 1 cm.", "between foam_brick mustard_bottle rubiks_cube"),
    ("mugbowl", "Displace the bowl 2 in toward the robot base, then return the arm to its home configuration.", "moved bowl back 0.0508; home"),
    ("fruitcans", "Translate the potted meat can 15 cm to the robot's right, then place the Rubik's cube directly behind it, ~100 mm centre to centre.", "moved meat_can right 0.15; behind rubiks_cube meat_can"),
    ("textkitchen", "Relocate the mug so it sits immediately to the right of the bowl, approx. 120 mm centre-to-centre.", "right mug bowl"),
    ("textblocks", "Push the green cube 3 inches toward the robot along the x-axis.", "moved cube@left back 0.0762"),
    ("scan45", "Move the red can 50 mm to the left in the robot frame; no rotation.", "moved red_can left 0.05"),
    ("scan55", "Push the orange cylinder 4 in (about 10 cm) to the robot's left.", "moved orange_cylinder left 0.1016"),
    # self-correcting / interrupting speaker
    ("kitchen", "Put the mug in the -- wait, no, next to the cracker box. Yeah, next to the box.", "next mug cracker_box"),
    ("pantry", "Grab the Rubik's -- no, scratch that, grab the foam brick and hold it up.", "lift foam_brick"),
    ("mugbowl", "Put the mug behind the bowl, no sorry, I mean to the left of the bowl.", "left mug bowl"),
    ("fruitcans", "put the can in the bowl -- no wait, not that one, the other one", "refuse"),
    ("textkitchen", "Put the cereal box, no, the mug, I mean the mug, put it in the bowl.", "in mug bowl"),
    ("textblocks", "Green cube onto the plate... wait, no, in front of the plate, not on it.", "front cube@left plate"),
    ("scan45", "Push the red box -- sorry, the red can -- push the red can toward you, like 5 cm.", "moved red_can back 0.05"),
    ("scan55", "Take the tall white can, no, I mean the smallest white thing, and put it on the green... the green flat thing.", "on small_white_object green"),
    # comparisons and conditions
    ("kitchen", "Take the smaller of the two, the soup can or the cracker box, and put it in the bowl.", "in soup_can bowl"),
    ("pantry", "Of the foam brick and the Rubik's cube, take whichever is smaller and put it behind the mustard.", "behind foam_brick mustard_bottle"),
    ("mugbowl", "If the mug fits in the bowl, put it in there; if not, just set it next to the bowl.", "in mug bowl"),
    ("fruitcans", "Whichever can is closer to the bowl, put that one in the bowl.", "in soup_can bowl"),
    ("textkitchen", "Take the soda can that's further away from you, the one at the back, and put it in the bowl.", "in soda_can@back bowl"),
    ("textblocks", "Take the cube that's closest to the plate and put it to the right of the plate.", "right cube@right plate"),
    ("scan45", "Of the two white cans, take the taller one and set it in front of the red can.", "front tall_white_can red_can"),
    ("scan55", "Put the yellow one in the bowl if it fits.", "refuse"),
]
