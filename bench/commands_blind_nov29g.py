"""Blind held-out command sentences (heldout24), written 2026-11-29 17:10 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT24: list[tuple[str, str, str]] = [
    # voice 1: quick notes with arrows, bullets, slashes and symbols
    ("kitchen", "soup can => bowl pls", "in tomato_soup_can bowl"),
    ("textblocks", "green cube -> between red & blue cubes", "between cube@green cube@red cube@blue"),
    ("pantry", "marker: left of the mustard / ty", "left large_marker mustard_bottle"),
    ("scan55", "\u2022 tall white can \u2192 white bowl", "in tall_white_can white_bowl"),
    ("fruitcans", "blue tin >> left side of rubik's cube", "left potted_meat_can rubiks_cube"),
    ("mugbowl", "1) mug fwd ~10cm 2) arm home", "moved mug forward 0.1; home"),
    ("scan45", "small white obj: off the big white thing, down on table", "table small_white_object"),
    ("textkitchen", "cereal box <-> mug (swap em)", "swapped cereal_box mug"),
    # voice 2: programmer half-writing code
    ("kitchen", "robot.push(cracker_box, direction='left', dist_cm=5)", "moved cracker_box left 0.05"),
    ("mugbowl", "arm.put(obj='mug', rel='behind', ref='bowl')", "behind mug bowl"),
    ("textblocks", "swap(cubes['blue'], cubes['green'])  # just trade their places", "swapped cube@blue cube@green"),
    ("scan55", 'pick("small white object"); place_next_to("orange cylinder")', "next small_white_object orange_cylinder"),
    ("fruitcans", "ok so basically place(rubiks_cube, between=[bowl, potted_meat_can])", "between rubiks_cube bowl potted_meat_can"),
    ("pantry", "Can you run put(potted_meat_can, in_front_of=foam_brick) for me?", "front potted_meat_can foam_brick"),
    ("textkitchen", "cereal_box.clear_away()  // it's in the way, move it somewhere else", "aside cereal_box"),
    ("scan45", "tall white can -> place(left_of='red can'), nothing else", "left left_tall_white_can red_can"),
    # voice 3: vague everyday amounts and hedges
    ("kitchen", "Could you nudge the mug a couple of inches to the right? Not far, just a couple.", "moved mug right 0.0508"),
    ("pantry", "The mustard is a bit far out, bring it back toward me maybe ten centimetres or so, about a hand's width.", "moved mustard_bottle back 0.1"),
    ("textblocks", "Hmm, I'd like the green cube just a touch further away from me, an inch, give or take.", "moved cube@green forward 0.0254"),
    ("scan55", "That orange cylinder, slide it left a bit, three-ish inches should do it.", "moved orange_cylinder left 0.0762"),
    ("mugbowl", "Maybe shift the bowl over to the right a tad? Five centimetres, roughly.", "moved bowl right 0.05"),
    ("fruitcans", "Just a hair closer to me with the soup can, a couple of centimetres at most.", "moved tomato_soup_can back 0.02"),
    ("textkitchen", "The soda can on the right, could it come toward me by roughly two inches?", "moved soda_can@right back 0.0508"),
    ("scan45", "Eh, the red box wants to go a little more to the right, say a couple of inches.", "moved red_box right 0.0508"),
    # voice 4: teacher quizzing a student, then asking for the action
    ("kitchen", "Which of these is the cracker box? Yes, the tall red one. Now set the soup can down right in front of it.", "front tomato_soup_can cracker_box"),
    ("mugbowl", "Where's the mug? Good, that's it. Now lift it up and hold it there.", "lift mug"),
    ("textblocks", "Tell me which cube is blue. Correct! Put that one behind the red cube.", "behind cube@blue cube@red"),
    ("scan55", "Can you see the tall white can sitting on the green box? Good. Take it off and stand it to the left of the white bowl.", "left tall_white_can white_bowl"),
    ("pantry", "Show me the Rubik's cube. Well done. It's in the way, so clear it aside please.", "aside rubiks_cube"),
    ("fruitcans", "Which fruit is farthest from us? The strawberry, exactly. Pop it into the bowl.", "in strawberry bowl"),
    ("textkitchen", "How many soda cans are there? Two, right. Take the one on the left and drop it in the bowl.", "in soda_can@left bowl"),
    ("scan45", "Which one is the red can? Good. Now pick it up for me.", "refuse"),
    # voice 5: a few words of a home language (Spanish, German, French, Hindi) mixed in
    ("kitchen", "Por favor, la banana, put it next to the soup can. Gracias!", "next banana tomato_soup_can"),
    ("pantry", "Den Marker bitte hinter den Rubik's cube, so behind the Rubik's cube. Danke!", "behind large_marker rubiks_cube"),
    ("textblocks", "Le cube rouge, the red one, on the plate s'il te pla\u00eet.", "on cube@red plate"),
    ("scan55", "Arre, jaldi se, push the blue box thoda forward, about 5 cm.", "moved blue_box forward 0.05"),
    ("mugbowl", "Mug ko bowl ke left mein rakh do, yaani left of the bowl, please.", "left mug bowl"),
    ("fruitcans", "Oye, el pl\u00e1tano... the banana, ponlo next to the Rubik's cube, porfa.", "next banana rubiks_cube"),
    ("textkitchen", "Alors, the mug, put it to the right of the cereal box, merci beaucoup.", "right mug cereal_box"),
    ("scan45", "Por favor, \u00e1brela, open the flat white box for me.", "refuse"),
    # voice 6: mixed multi-step tasks and requests the robot must decline
    ("kitchen", "Pour the tomato soup into the red bowl.", "refuse"),
    ("textkitchen", "Pick up the soda can, please.", "refuse"),
    ("pantry", "Put the scissors next to the mustard bottle.", "refuse"),
    ("scan55", "Pick up the red box and drop it into the white bowl.", "refuse"),
    ("mugbowl", "Put the mug in the bowl and then go back to your home position.", "in mug bowl; home"),
    ("textblocks", "First stack the green cube on the red one, then move the blue cube to where the green cube was, and then head home.", "on cube@green cube@red; spot cube@blue cube@green; home"),
    ("fruitcans", "Put the strawberry between the banana and the blue tin, then push the Rubik's cube 3 cm to the left.", "between strawberry banana potted_meat_can; moved rubiks_cube left 0.03"),
    ("scan45", "Put the right white can in front of the red can, then nudge the tall white can 4 cm left.", "front right_white_can red_can; moved left_tall_white_can left 0.04"),
]
