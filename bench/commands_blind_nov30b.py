"""Blind held-out command sentences (heldout34), written 2026-11-30 03:58 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT34: list[tuple[str, str, str]] = [
    # voice 1: a small child (about six) talking straight to the robot -- simple words, "pleeease", excited asides, calls the mug a cup
    ("kitchen", "robot!! put the banana next to the cup pleeease, the red cup with the handle", "next banana mug"),
    ("fruitcans", "the strawberry is all lonely so put it by the banana and then they can be friends", "next strawberry banana"),
    ("textblocks", "I want the blue block on the plate. The BLUE one, not the red one!", "on cube@blue plate"),
    ("pantry", "Can you pick up the Rubik's cube? The one with all the colours. Up high!", "lift rubiks_cube"),
    ("mugbowl", "put the cup inside the bowl, it's going on a boat ride", "in mug bowl"),
    ("scan55", "pick up the big orange cylinder and make it fly like a spaceship!!", "refuse"),
    ("textkitchen", "um the cereal box goes in front of the bowl. In front means closer to you ok", "front cereal_box bowl"),
    ("scan45", "the small white object is sitting on the big white object and it's not allowed, put it down on the table", "table small_white_object"),

    # voice 2: someone passing on what another person asked for (reported speech: "my flatmate says...", "the client wants...")
    ("pantry", "My flatmate says the marker's been left lying around again -- she wants it next to the mustard bottle.", "next large_marker mustard_bottle"),
    ("kitchen", "Dana asked me to pass this on: the soup can should be behind the cracker box, not out in the open.", "behind tomato_soup_can cracker_box"),
    ("scan45", "The lab manager wants the left tall white can over on the left side of the red can. Her words, not mine.", "left left_tall_white_can red_can"),
    ("scan55", "Per Jamal, the red box belongs to the left of the white bowl.", "left red_box white_bowl"),
    ("fruitcans", "My daughter insists the strawberry goes in the bowl, because that's 'where fruit lives'.", "in strawberry bowl"),
    ("textblocks", "Coach told me to tell you to swap the red cube and the green cube around.", "swapped cube@red cube@green"),
    ("mugbowl", "The client would like the mug slid ten centimetres forward; apparently it looks too close to the edge.", "moved mug forward 0.1"),
    ("textkitchen", "My husband wants you to open the cereal box and pour some into the bowl for him.", "refuse"),

    # voice 3: names things only by material, texture or feel (the squishy foam one, the cardboard one, the metal tin, the plastic cup)
    ("pantry", "Grab the squishy foam thing and set it down to the right of the metal tin.", "right foam_brick potted_meat_can"),
    ("kitchen", "Nudge the cardboard box about five centimetres to the left.", "moved cracker_box left 0.05"),
    ("mugbowl", "Lift the hard plastic cup by its handle and just hold it there.", "lift mug"),
    ("fruitcans", "That rubbery little berry -- move it so it sits in front of the rectangular tin.", "front strawberry potted_meat_can"),
    ("textblocks", "The red wooden block, set it on the ceramic plate.", "on cube@red plate"),
    ("textkitchen", "Push the cardboard one eight centimetres away from yourself.", "moved cereal_box forward 0.08"),
    ("pantry", "Could you pick up the soft plastic squeeze bottle?", "lift mustard_bottle"),
    ("mugbowl", "The wide plastic dish is fine where it is; the little plastic cup, though, belongs on its left.", "left mug bowl"),

    # voice 4: a product stylist setting up a photo shoot -- "hero", "in shot", "out of frame", "reads as a pair"
    ("scan55", "For this shot the orange cylinder has to go. Just get it out of the way.", "aside orange_cylinder"),
    ("scan45", "Hero product is the red box. Bring it in next to the red can so they read as a pair.", "next red_box red_can"),
    ("kitchen", "Styling note: the banana looks lost. Tuck it just in front of the bowl.", "front banana bowl"),
    ("textblocks", "I want the blocks in a line with the green one sitting between the red and the blue.", "between cube@green cube@red cube@blue"),
    ("pantry", "Swap the mustard and the Rubik's cube, the yellow should be on the right-hand side of the set.", "swapped mustard_bottle rubiks_cube"),
    ("fruitcans", "Banana's eating the whole frame. Slide it four inches to the right.", "moved banana right 0.1016"),
    ("textkitchen", "Still life idea: pop the left soda can into the bowl.", "in soda_can@left bowl"),
    ("scan45", "The red can is crowding everything, slide it six centimetres left.", "moved red_can left 0.06"),

    # voice 5: an elderly person not used to machines, talks to the robot like a kind helper, old-fashioned names (luncheon meat, cheese crackers, dinner plate)
    ("kitchen", "Would you fetch that box of cheese crackers for me, dear? Just lift it up so I can see it.", "lift cracker_box"),
    ("pantry", "The tin of luncheon meat, love -- pop it next to that puzzle cube, the coloured one.", "next potted_meat_can rubiks_cube"),
    ("mugbowl", "Now then, I don't like that cup sitting out there. Put it behind the bowl, would you.", "behind mug bowl"),
    ("fruitcans", "My eyes aren't what they were. Put the tin of tomato soup in the bowl so I know where it is.", "in tomato_soup_can bowl"),
    ("textkitchen", "I can't manage the cereal box with these hands of mine. Set it beside the cup for me, there's a good fellow.", "next cereal_box mug"),
    ("scan45", "Young man -- or whatever you are -- that left tall white can, I'd like it in front of the red can please.", "front left_tall_white_can red_can"),
    ("scan55", "The tall white can perched on the green box worries me. Set it down on the table where it's safe, dear.", "table tall_white_can"),
    ("textblocks", "That dinner plate's a bit far off. Draw it towards yourself a couple of inches.", "moved plate back 0.0508"),

    # voice 6: mixed two- and three-step tasks, and requests the robot must decline
    ("kitchen", "Put the soup can in the bowl, then bring the arm home.", "in tomato_soup_can bowl; home"),
    ("scan55", "Take the third-from-left yellow object off what it's on and put it on the table, then set the white box next to it.", "table third_from_left_yellow_object; next white_box third_from_left_yellow_object"),
    ("fruitcans", "Swap the banana and the strawberry, and after that push the Rubik's cube 3 cm forward.", "swapped banana strawberry; moved rubiks_cube forward 0.03"),
    ("pantry", "Move the marker out of the way, put the foam brick where the marker was, then go home.", "aside large_marker; spot foam_brick large_marker; home"),
    ("scan45", "Pick up the red can and hold it up for me.", "refuse"),
    ("textkitchen", "Grab the soda can and put it next to the bowl.", "refuse"),
    ("mugbowl", "Put the spoon in the mug.", "refuse"),
    ("textblocks", "Lift the plate up and slide the red cube under it.", "refuse"),
]
