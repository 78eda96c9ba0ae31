"""Blind held-out command sentences (heldout28), written 2026-11-29 19:55 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT28: list[tuple[str, str, str]] = [
    # voice 1: names things only by their kind or use, never by the list's words
    ("kitchen", "Could you drop the fruit into the dish for me?", "in banana bowl"),
    ("kitchen", "The coffee cup, set it down right beside the snack packet.", "next mug cracker_box"),
    ("pantry", "Grab the yellow sauce and just hold it up in the air.", "lift mustard_bottle"),
    ("pantry", "I think the puzzle would look better sitting to the left of the condiment.", "left rubiks_cube mustard_bottle"),
    ("fruitcans", "That little red fruit at the back, pop it in the dish please.", "in strawberry bowl"),
    ("mugbowl", "Cup goes in front of the dish.", "front mug bowl"),
    ("textkitchen", "Can you get the breakfast carton out of the way? It's blocking everything.", "aside cereal_box"),
    ("scan55", "Nudge the thing you'd eat your cornflakes out of about 5 cm further away.", "moved white_bowl forward 0.05"),
    # voice 2: describes the end result by comparison or distance
    ("mugbowl", "I want the bowl to end up closer to me than the mug is.", "front bowl mug"),
    ("kitchen", "The banana should be right up against the bowl when you're done.", "next banana bowl"),
    ("fruitcans", "Make it so the Rubik's cube is farther from me than the blue tin.", "behind rubiks_cube potted_meat_can"),
    ("textblocks", "Get the green cube to within a couple of centimetres of the blue one.", "next cube@green cube@blue"),
    ("pantry", "By the end, the marker should be further left than the mustard bottle.", "left large_marker mustard_bottle"),
    ("textkitchen", "Leave the bowl roughly a hand's width from the mug, no more than that.", "next bowl mug"),
    ("scan45", "The tall white can ought to be nearer to me than the red can is.", "front left_tall_white_can red_can"),
    ("scan55", "I'd like the orange cylinder about ten centimetres further from me than it is now.", "moved orange_cylinder forward 0.1"),
    # voice 3: a teacher giving numbered or ordered steps in one message
    ("fruitcans", "Step 1: take the banana. Step 2: place it in the bowl. Step 3: return home.", "in banana bowl; home"),
    ("textblocks", "1) Put the blue cube on the plate. 2) Then set the green cube next to it. 3) Go back to home.", "on cube@blue plate; next cube@green cube@blue; home"),
    ("kitchen", "Let's practise. First, slide the soup can 5 cm to the right. Next, lift the mug. Last of all, return to your home pose.", "moved tomato_soup_can right 0.05; lift mug; home"),
    ("pantry", "Step one, put the foam brick on top of the potted meat can. Step two, move the Rubik's cube out of the way.", "on foam_brick potted_meat_can; aside rubiks_cube"),
    ("mugbowl", "First: put the mug in the bowl. Second: take it back out and return it to where it was.", "in mug bowl; at mug"),
    ("textkitchen", "Here is the order. One, move the mug out of the way. Two, put the left soda can where the mug was. Three, go home.", "aside mug; spot soda_can@left mug; home"),
    ("scan45", "Watch carefully. To begin, take the small white object off the big white object and set it on the table. After that, put it to the left of the red can.", "table small_white_object; left small_white_object red_can"),
    ("scan55", "1. Lift the small white object. 2. Put it in the white bowl. 3. Return to your start position.", "in small_white_object white_bowl; home"),
    # voice 4: a sarcastic or frustrated user
    ("kitchen", "Seriously? The mug is STILL over on the right. Put it to the left of the cracker box, like I asked ten minutes ago.", "left mug cracker_box"),
    ("pantry", "Wow. Incredible. The marker hasn't moved an inch. Push it forward 3 inches already.", "moved large_marker forward 0.0762"),
    ("mugbowl", "Sure, take your time. Whenever you're ready, the mug goes behind the bowl.", "behind mug bowl"),
    ("fruitcans", "Great, you've done nothing useful all day, so how about you pour the soup into the bowl, genius?", "refuse"),
    ("textkitchen", "Ugh, why is the left soda can still sitting there? Get it out of my way.", "aside soda_can@left"),
    ("textblocks", "Red cube. Plate. On it. How hard can that possibly be?", "on cube@red plate"),
    ("scan45", "Oh sure, just leave the right white can perched on that flat box forever. Put it on the table, would you.", "table right_white_can"),
    ("scan55", "Amazing, the orange cylinder is still exactly where it was. Shove it 10 centimetres to the right, if that's not too much trouble.", "moved orange_cylinder right 0.1"),
    # voice 5: a non-native speaker with grammar mistakes and word-for-word translations
    ("kitchen", "Please you take the soup can and you put it at the side of banana.", "next tomato_soup_can banana"),
    ("pantry", "The brick of foam, make it go behind of the Rubik cube.", "behind foam_brick rubiks_cube"),
    ("mugbowl", "Mug, you do it more at left, 10 centimetre.", "moved mug left 0.1"),
    ("fruitcans", "You can change the place of the banana with the place of strawberry?", "swapped banana strawberry"),
    ("textkitchen", "Put the can of soda of the right side inside of bowl, please.", "in soda_can@right bowl"),
    ("textblocks", "The cube green, you put him between the red and the blue.", "between cube@green cube@red cube@blue"),
    ("scan55", "Do the white box more at left, 5 centimetre only.", "moved white_box left 0.05"),
    ("scan45", "Take the can white of the right and put him on the left of the tall can white.", "left right_white_can left_tall_white_can"),
    # voice 6: mixed two- and three-step tasks and requests the robot must decline
    ("pantry", "Stack the foam brick on the Rubik's cube, then slide the marker 5 cm to the left.", "on foam_brick rubiks_cube; moved large_marker left 0.05"),
    ("fruitcans", "Move the soup can next to the blue tin, put the strawberry in the bowl, and then go home.", "next tomato_soup_can potted_meat_can; in strawberry bowl; home"),
    ("textkitchen", "Put the soda can in the bowl.", "refuse"),
    ("mugbowl", "Can you fill the mug with water from the bowl?", "refuse"),
    ("kitchen", "Open the cracker box and hand me a cracker.", "refuse"),
    ("scan55", "Pick up the red box and drop it in the white bowl.", "refuse"),
    ("textblocks", "Put the yellow cube on the plate.", "refuse"),
    ("scan45", "Put the right white can in front of the red can, then push the red box 5 cm back toward me.", "front right_white_can red_can; moved red_box back 0.05"),
]
