"""Blind held-out command sentences written on 2026-11-29 (``--set heldout18``).

Written at 11:14 UTC by a helper that read nothing of the repository (only the scenes' object lists
in the robot's frame, the goal words and a brief of eight voices: a lab technician, a polite elderly
person, a child, a non-native speaker, a fast phone typist, objects named only by look or place,
two- and three-step tasks, refusals mixed with hedged requests), added verbatim. Kept sealed from
the helper working on the planner. Measured with ``--plans``: 35/64 at the session's start
(0d68aa8) and 35/64 after that helper's work (2e6b9c6); then read, and its failures' classes fixed
(wishes, chat spelling, lift heights, "X, you put him ..."): 58/64, no longer blind.
"""
from __future__ import annotations

HELDOUT18: list[tuple[str, str, str]] = [
    # kitchen
    ("kitchen", "Banana right of cracker box.", "right banana cracker_box"),
    ("kitchen", "Good afternoon, dear robot. If it isn't too much trouble, would you kindly pick up that tomato soup can and set it down beside the mug? Thank you ever so much.", "next tomato_soup_can mug"),
    ("kitchen", "yo robot grab the mug and hold it up high!!", "lift mug"),
    ("kitchen", "Please you are moving the banana to the left side, ten centimetre.", "moved banana left 0.10"),
    ("kitchen", "cn u stick the soup cn in teh bowl thx", "in tomato_soup_can bowl"),
    ("kitchen", "Put the cup with the handle behind the round dish at the back.", "behind mug bowl"),
    ("kitchen", "Lift the mug and set it down in front of the bowl, then nudge the banana 4 cm to the right, and go home.", "front mug bowl; moved banana right 0.04; home"),
    ("kitchen", "Could you maybe put the apple in the bowl?", "refuse"),
    # pantry
    ("pantry", "Foam brick on rubiks cube.", "on foam_brick rubiks_cube"),
    ("pantry", "Oh hello there. I wonder if you would be so good as to shift the mustard bottle towards me by about five centimetres; my eyes are not what they once were.", "moved mustard_bottle back 0.05"),
    ("pantry", "lift the marker up yay", "lift large_marker"),
    ("pantry", "The potted meat can, you put him at beside of the mustard bottle please.", "next potted_meat_can mustard_bottle"),
    ("pantry", "mve rubiks cube 2 inches rght pls", "moved rubiks_cube right 0.0508"),
    ("pantry", "Stand the tallest thing on the table behind the small brick in the middle.", "behind mustard_bottle foam_brick"),
    ("pantry", "Lay the large marker on the foam brick, then slide the rubiks cube 4 cm to the left, then park the arm.", "on large_marker foam_brick; moved rubiks_cube left 0.04; home"),
    ("pantry", "It would be nice if the foam brick were sitting in front of the mustard bottle, if that's not a bother.", "front foam_brick mustard_bottle"),
    # mugbowl
    ("mugbowl", "Mug in bowl.", "in mug bowl"),
    ("mugbowl", "Would you be a dear and slide the bowl over to the right, say a good four inches or so? Thank you kindly, I do appreciate it.", "moved bowl right 0.1016"),
    ("mugbowl", "put the cup next to the big bowl pls", "next mug bowl"),
    ("mugbowl", "Take the mug and make it go up in the air, and hold.", "lift mug"),
    ("mugbowl", "swp the mug n bowl plz", "swapped mug bowl"),
    ("mugbowl", "Put the small handled thing on the right over to the left of the wide round dish.", "left mug bowl"),
    ("mugbowl", "Set the mug behind the bowl, then nudge the bowl 3 cm towards you, then return to rest.", "behind mug bowl; moved bowl back 0.03; home"),
    ("mugbowl", "Could you maybe tuck the bowl inside the mug?", "refuse"),
    # fruitcans
    ("fruitcans", "Lift banana.", "lift banana"),
    ("fruitcans", "If it would not be too much bother, I should very much like the tomato soup can to be set right beside the potted meat can, there's a good machine.", "next tomato_soup_can potted_meat_can"),
    ("fruitcans", "can u put the cube in the bowl lol", "in rubiks_cube bowl"),
    ("fruitcans", "Potted meat can must going to the right by 6 centimetre.", "moved potted_meat_can right 0.06"),
    ("fruitcans", "put strwbery rite of the meat cn", "right strawberry potted_meat_can"),
    ("fruitcans", "Set the narrow tall can at the front left down in front of the squat can in the middle.", "front tomato_soup_can potted_meat_can"),
    ("fruitcans", "Drop the strawberry into the bowl, place the banana next to the bowl, then go home.", "in strawberry bowl; next banana bowl; home"),
    ("fruitcans", "Could you possibly put the orange next to the banana?", "refuse"),
    # textkitchen
    ("textkitchen", "Front soda can, right of bowl.", "right soda_can@front bowl"),
    ("textkitchen", "Hello, my dear. Would you mind terribly lifting that white mug up off the table for a moment? I'd like to have a good look at it.", "lift mug"),
    ("textkitchen", "make the mug go on the other side of the cereal box hehe", "right mug cereal_box"),
    ("textkitchen", "Please the cereal box you are pushing 50 millimetre to forward.", "moved cereal_box forward 0.05"),
    ("textkitchen", "put teh soda can on teh rite nxt 2 the bowl", "next soda_can@right bowl"),
    ("textkitchen", "Put the red can farthest from me in the white round dish.", "in soda_can@back bowl"),
    ("textkitchen", "Place the mug in the bowl, then bring the left soda can in front of the cereal box, then go home.", "in mug bowl; front soda_can@left cereal_box; home"),
    ("textkitchen", "Would you mind popping the soda can into the bowl?", "refuse"),
    # textblocks
    ("textblocks", "Red cube on plate.", "on cube@red plate"),
    ("textblocks", "Good morning. If you would be so kind, I'd like the blue cube stacked neatly on top of the red one. Thank you, young robot.", "on cube@blue cube@red"),
    ("textblocks", "move green block to the left like 4 cm", "moved cube@green left 0.04"),
    ("textblocks", "Put the green cube in between of red cube and blue cube.", "between cube@green cube@red cube@blue"),
    ("textblocks", "mov red cube 3in fwd pls", "moved cube@red forward 0.0762"),
    ("textblocks", "Put the block farthest to the left in front of the big flat round thing.", "front cube@green plate"),
    ("textblocks", "Stack the green cube on the blue cube, then slide the plate 5 cm to the right, then go home.", "on cube@green cube@blue; moved plate right 0.05; home"),
    ("textblocks", "It'd be lovely if the blue cube were sitting right next to the plate, if you could manage it.", "next cube@blue plate"),
    # scan45
    ("scan45", "Small white object next to red box.", "next small_white_object red_box"),
    ("scan45", "Would you be so kind as to nudge the red box about four centimetres to the right? I'd be much obliged, thank you.", "moved red_box right 0.04"),
    ("scan45", "lift the red can way up high!!", "lift red_can"),
    ("scan45", "Left tall white can, you must to put it in front of the red can.", "front left_tall_white_can red_can"),
    ("scan45", "pls mve red cn 2 in to teh left", "moved red_can left 0.0508"),
    ("scan45", "Take the little can perched on the wide flat box and stand it on the table to the right of the big box on the far right.", "table right_white_can; right right_white_can red_box"),
    ("scan45", "Move the red can 5 cm towards me, then put the right white can next to it, then go home.", "moved red_can back 0.05; next right_white_can red_can; home"),
    ("scan45", "I was sort of hoping the left tall white can could end up to the left of the red can, if that's doable?", "left left_tall_white_can red_can"),
    # scan55
    ("scan55", "Small white object into white bowl.", "in small_white_object white_bowl"),
    ("scan55", "Would you be so very kind as to take the tall white can down off the green box and stand it on the table to the left of the orange cylinder? Thank you, dear.", "table tall_white_can; left tall_white_can orange_cylinder"),
    ("scan55", "lift the big white object up really high!!", "lift big_white_object"),
    ("scan55", "Orange cylinder, you are sliding it to left side 5 centimetre.", "moved orange_cylinder left 0.05"),
    ("scan55", "put teh big wht obj in frnt of teh orng cylinder", "front big_white_object orange_cylinder"),
    ("scan55", "Put the thin flat piece in the front right corner on top of the wide round thing in the middle.", "on small_white_object orange_cylinder"),
    ("scan55", "Put the tall white can in the white bowl, then set the small white object next to the orange cylinder, and go home.", "in tall_white_can white_bowl; next small_white_object orange_cylinder; home"),
    ("scan55", "Would you mind grabbing the yellow object for me?", "refuse"),
]
