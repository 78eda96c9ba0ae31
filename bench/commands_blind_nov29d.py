"""Blind held-out command sentences written on 2026-11-29, fourth batch (``--set heldout21``).

Written at 14:50 UTC by a helper that read nothing of the repository (only the scenes' object lists
in the robot's frame, the goal words and a brief of six voices: a formal office email, a drill
sergeant, things named only by their relation to other things, an unsure speaker asking rather
than telling, odd amounts and units, multi-step tasks mixed with requests to decline), added
verbatim after held-out 20's fixes. Measured with ``--plans``: 19/48 at d15e3d9 (the session's
start), 19/48 at df47e56 (held-out 20's fixes) and 19/48 with "nearest you" measured from the base
(nothing in it tuned for these). Then read, and its failures' classes fixed (an office email's frame
and passive requests, a drill sergeant's urging, terse "X! Forward ten centimetres!", questions that
ask for a place, spoken fractions and trade units, "the marker needs to come back ..."): 42/48, no
longer blind (left: the potted meat named by a colour the YCB scenes do not record, things named
only by a relation to a neighbour standing off to its side, a lift undone by "put it back", a
lift of a box wider than the hand that is planned and then declined by the grasp).
"""
from __future__ import annotations

HELDOUT21: list[tuple[str, str, str]] = [
    # voice 1: formal office email
    ("kitchen", "Kindly be advised that the cracker box needs to be relocated to the left-hand side of the soup can. Regards, Martin", "left cracker_box tomato_soup_can"),
    ("pantry", "Per my earlier request, please ensure the potted meat tin is relocated to the left of the mustard bottle. Thank you in advance for your cooperation.", "left potted_meat_can mustard_bottle"),
    ("mugbowl", "Following up on this morning's note: the mug should be positioned in front of the bowl, that is, on the side nearest the robot. Best regards.", "front mug bowl"),
    ("fruitcans", "I would be grateful if the potted meat tin could be placed behind the Rubik's cube, after which the arm should return to its home position. Kind regards, J. Patel", "behind potted_meat_can rubiks_cube; home"),
    ("textkitchen", "As discussed in Tuesday's meeting, please arrange for the mug to be placed behind the cereal box. Many thanks.", "behind mug cereal_box"),
    ("textblocks", "Please be informed that the green cube is to be relocated to the right of the plate at your earliest convenience. Regards, Facilities Team", "right cube@green plate"),
    ("scan45", "With reference to the items currently on the workbench, kindly ensure the small white object ends up to the right of the red box. Sincerely, Operations", "right small_white_object red_box"),
    ("scan55", "Further to my previous message, I must ask that the big white object be transferred into the white bowl. Thank you for your prompt attention to this matter.", "in big_white_object white_bowl"),

    # voice 2: coach / drill sergeant
    ("kitchen", "Soup can! In front of the cracker box! Move, move, move!", "front tomato_soup_can cracker_box"),
    ("pantry", "Marker up! Off the deck! Good. Now put it back exactly where it was, soldier!", "lift large_marker; at large_marker"),
    ("mugbowl", "Mug. Next to the bowl. I said NOW! Hustle!", "next mug bowl"),
    ("fruitcans", "Get that Rubik's cube in the bowl! Double time! Go, go, go!", "in rubiks_cube bowl"),
    ("textkitchen", "Left soda can, over by the bowl, on the double! Then back to home position! Move it!", "next soda_can@left bowl; home"),
    ("textblocks", "Red cube! Forward ten centimetres! Don't make me repeat myself!", "moved cube@red forward 0.1"),
    ("scan45", "You! Red can! Shove it forward five centimetres, now! Pick up the pace!", "moved red_can forward 0.05"),
    ("scan55", "Blue box, forward, five centimetres! Push it! Go!", "moved blue_box forward 0.05"),

    # voice 3: objects named only by their relation to other objects
    ("kitchen", "Whatever's standing behind the cracker box over on the left, drop it into the bowl.", "in tomato_soup_can bowl"),
    ("pantry", "Grab the object that sits between the mustard bottle and the blue tin and lift it up.", "lift foam_brick"),
    ("mugbowl", "The thing closest to the robot goes into the thing farther away.", "in mug bowl"),
    ("fruitcans", "Take the thing directly behind the blue tin and set it to the left of the banana.", "left strawberry banana"),
    ("textkitchen", "Of the two cans, the one nearer the mug should go in the bowl.", "in soda_can@right bowl"),
    ("textblocks", "The block sitting between the other two blocks, put that one on the plate.", "on cube@blue plate"),
    ("scan45", "Whatever is sitting on top of the flat white box, take it off and put it on the table.", "table right_white_can"),
    ("scan55", "Lift up whatever's standing on the green box.", "lift tall_white_can"),

    # voice 4: unsure speaker asking rather than telling
    ("kitchen", "Um, could the mug maybe go next to the banana?", "next mug banana"),
    ("pantry", "Would it be possible to put the Rubik's cube behind the mustard bottle? Only if it's no trouble.", "behind rubiks_cube mustard_bottle"),
    ("mugbowl", "Is there any way the mug could end up on the left side of the bowl?", "left mug bowl"),
    ("fruitcans", "I'm not sure if this works, but could the banana and the soup can trade places?", "swapped banana tomato_soup_can"),
    ("textkitchen", "Sorry, would you mind moving the cereal box out of the way, and then maybe the mug could go where the cereal box used to be?", "aside cereal_box; spot mug cereal_box"),
    ("textblocks", "Hmm, do you think the red cube could sit between the blue one and the green one?", "between cube@red cube@blue cube@green"),
    ("scan45", "Could the tall white can perhaps go in front of the red can? I think that would look better.", "front left_tall_white_can red_can"),
    ("scan55", "Maybe the orange cylinder could be slid a little to the left... five centimetres or so, if that's possible?", "moved orange_cylinder left 0.05"),

    # voice 5: odd amounts and units
    ("kitchen", "Banana, half an inch toward me.", "moved banana back 0.0127"),
    ("pantry", "Shift the foam brick a couple of inches to the left.", "moved foam_brick left 0.0508"),
    ("pantry", "The marker needs to come back ten mil, nearer the robot.", "moved large_marker back 0.01"),
    ("mugbowl", "Slide the bowl 0.05 metres to the right.", "moved bowl right 0.05"),
    ("fruitcans", "Push the Rubik's cube right by about a finger's width, say two centimetres.", "moved rubiks_cube right 0.02"),
    ("textblocks", "Green cube: two and a half centimetres back toward the robot, please.", "moved cube@green back 0.025"),
    ("scan45", "Could you scoot the small white object three quarters of an inch to the left?", "moved small_white_object left 0.01905"),
    ("scan55", "White bowl, a hand's width to the left. Call it ten centimetres.", "moved white_bowl left 0.1"),

    # voice 6: mixed multi-step tasks and requests that must be declined
    ("kitchen", "Pour the soup from the can into the red bowl.", "refuse"),
    ("pantry", "Grab the tennis ball and drop it next to the mustard.", "refuse"),
    ("mugbowl", "Pick up the mug, and while you're holding it, put the bowl inside it.", "refuse"),
    ("fruitcans", "First the strawberry goes in the bowl, then put the banana next to the soup can, and finish by going back home.", "in strawberry bowl; next banana tomato_soup_can; home"),
    ("textkitchen", "Put the red soda can in the bowl.", "refuse"),
    ("textblocks", "Put the yellow cube on the plate, then go home.", "refuse"),
    ("scan45", "Swap the right white can with the tall white can and then return home.", "swapped right_white_can left_tall_white_can; home"),
    ("scan55", "Lift the red box up off the table.", "refuse"),
]
