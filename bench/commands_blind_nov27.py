"""Blind held-out command sentences written on 2026-11-27 (``--set heldout17``).

Written at 03:10 UTC by someone who never read the planner, its tests, the other sets or any file of
the repository (only the scenes' object lists, positions and the goal words), added verbatim. Kept
sealed from everyone working on the planner until that session's planner work was done, and
measured at its start (dee51ce: 27/48, 2 acting wrongly) and at its end (8789baa: 31/48, 2 acting
wrongly). Six kinds of people: a nurse, a non-native speaker, a fast phone typist, two- and
three-step tasks, things named by position or relation only, indirect and hedged requests.
"""
from __future__ import annotations

HELDOUT17: list[tuple[str, str, str]] = [
    # nurse
    ("kitchen", "Could you put the cup in the soup bowl for me, please?", "in mug bowl"),
    ("pantry", "Please pick up the mustard and just hold it up there for a moment.", "lift mustard_bottle"),
    ("mugbowl", "Set the drinking mug down in front of the bowl, on the side closest to you, please.", "front mug bowl"),
    ("fruitcans", "The strawberry is a bit out of reach, bring it about ten centimetres back towards you, please.", "moved strawberry back 0.1"),
    ("textkitchen", "Could you put the fizzy drink can beside the cereal box, please?", "refuse"),
    ("textblocks", "Please put the green block in between the red one and the blue one.", "between cube@green cube@red cube@blue"),
    ("scan45", "Please stand the tall white can in front of the red can, on your side of it.", "front tall_white_can red_can"),
    ("scan55", "The white dish, the one we use for soup, please move it to the left of the orange cylinder.", "left white_bowl orange_cylinder"),
    # non-native speaker
    ("kitchen", "You put the cracker box at behind of the bowl, please.", "behind cracker_box bowl"),
    ("pantry", "Please the foam brick, put it in right side of the mustard.", "right foam_brick mustard_bottle"),
    ("mugbowl", "Push the mug to the left for 5 centimeter.", "moved mug left 0.05"),
    ("fruitcans", "Change place of banana with strawberry, each one go where is the other.", "swapped banana strawberry"),
    ("textkitchen", "Put the cup in front from the bowl, more near of you.", "front mug bowl"),
    ("textblocks", "Red cube, make it go more far from you, 80 millimeter.", "moved cube@red forward 0.08"),
    ("scan45", "Please take the banana and put near to red box.", "refuse"),
    ("scan55", "The red box, push it to your direction, 5 cm only.", "moved red_box back 0.05"),
    # fast phone typist
    ("kitchen", "pls put teh soup can nxt to the mug", "next soup_can mug"),
    ("pantry", "slide teh markr fwd like 3 inches", "moved marker forward 0.0762"),
    ("mugbowl", "pick up the bowl n hold it up pls", "lift bowl"),
    ("fruitcans", "put rubiks cube bhind the meat can", "behind rubiks_cube potted_meat_can"),
    ("textkitchen", "swap the mug w/ the cereal box thx", "swapped mug cereal_box"),
    ("textblocks", "red cube on top of teh green one pls", "on cube@red cube@green"),
    ("scan45", "ok thats all, go bakc home pls", "home"),
    ("scan55", "nudge the white bowl 50mm to teh left", "moved white_bowl left 0.05"),
    # multi-step
    ("kitchen", "Put the banana in the bowl and then move the soup can so it sits right behind the mug.", "in banana bowl; behind soup_can mug"),
    ("pantry", "Move the foam brick next to the marker, and after that push the Rubik's cube two inches forward.", "next foam_brick marker; moved rubiks_cube forward 0.0508"),
    ("mugbowl", "Put the mug to the left of the bowl, and once you're done, go back to your home position.", "left mug bowl; home"),
    ("fruitcans", "Two things: 1) put the Rubik's cube in the bowl, 2) slide the potted meat can 5 cm to your left.", "in rubiks_cube bowl; moved potted_meat_can left 0.05"),
    ("textkitchen", "Take the left soda can and put it in front of the mug, then after that put the other soda can behind the mug.", "front soda_can@left mug; behind soda_can@right mug"),
    ("textblocks", "Stack the blue cube on the red cube, and then put the green cube on top of the blue one.", "on cube@blue cube@red; on cube@green cube@blue"),
    ("scan45", "Nudge the red can 4 cm to your left and then pick up the tall white can and hold it up.", "moved red_can left 0.04; lift tall_white_can"),
    ("scan55", "Lift the tall white can, put it back down exactly where it was, and after that return to home.", "lift tall_white_can; at tall_white_can; home"),
    # position / relation only
    ("kitchen", "Pick up whatever is closest to you and hold it in the air.", "lift banana"),
    ("pantry", "Take the object that's furthest to your left and put it in front of the tallest thing on the table.", "front marker mustard_bottle"),
    ("mugbowl", "Put the nearer of the two objects into the farther one.", "in mug bowl"),
    ("fruitcans", "Whatever is sitting furthest back on the table, put it in the bowl.", "in strawberry bowl"),
    ("textkitchen", "The can that's further back, put it behind the box.", "behind soda_can@back cereal_box"),
    ("textblocks", "Put the block in the middle of the three onto the big flat thing.", "on cube@blue plate"),
    ("scan45", "Take the can at the very back and stand it to the left of the can that's nearest to you.", "left tall_white_can red_can"),
    ("scan55", "Pick up the thing behind the blue one.", "refuse"),
    # indirect / hedging
    ("kitchen", "I was wondering if you could slide the cracker box about 10 cm towards yourself?", "moved cracker_box back 0.1"),
    ("pantry", "Would it be possible to lift the potted meat can for a second and then set it back down where it was?", "lift potted_meat_can; at potted_meat_can"),
    ("mugbowl", "Would it be possible to put the spoon in the bowl?", "refuse"),
    ("fruitcans", "It'd be great if the soup can ended up between the bowl and the potted meat can.", "between soup_can bowl potted_meat_can"),
    ("textkitchen", "Would you mind nudging the cereal box maybe two inches further away from you?", "moved cereal_box forward 0.0508"),
    ("textblocks", "It'd be lovely if the red cube and the blue cube could trade places, if that's alright.", "swapped cube@red cube@blue"),
    ("scan45", "I was hoping you could fit the red box inside the red can?", "refuse"),
    ("scan55", "Ideally the tall white can would end up standing to the left of the white bowl, if you can manage it.", "left tall_white_can white_bowl"),
]
