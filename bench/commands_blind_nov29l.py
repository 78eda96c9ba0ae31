"""Blind held-out command sentences (heldout29), written 2026-11-29 22:31 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT29: list[tuple[str, str, str]] = [
    # voice 1: voice dictation with transcription slips (homophones, split/run-together words, no punctuation, spelled-out numbers)
    ("kitchen", "ok robot put the tomato soup can next too the red mud", "next tomato_soup_can mug"),
    ("pantry", "pick up the rubix cube than put it back were it was", "lift rubiks_cube; at rubiks_cube"),
    ("mugbowl", "can you move the mug so its next two the bowel", "next mug bowl"),
    ("fruitcans", "rubics cube goes behind the potted meet can please", "behind rubiks_cube potted_meat_can"),
    ("textkitchen", "move the left soda can behind the serial box", "behind soda_can@left cereal_box"),
    ("textblocks", "put the blew cube on the plate thank you", "on cube@blue plate"),
    ("scan45", "push the left tall white can back words five centimeters towards the robot", "moved left_tall_white_can back 0.05"),
    ("scan55", "now push the orange cylinder two the left ten centimeters", "moved orange_cylinder left 0.10"),
    # voice 2: picks objects only by position or order
    ("kitchen", "The leftmost object: put that in front of the thing immediately to its right.", "front tomato_soup_can cracker_box"),
    ("pantry", "Whatever is farthest back, set it down on the right side of the one nearest you.", "right large_marker potted_meat_can"),
    ("mugbowl", "Put the closer one into the farther one.", "in mug bowl"),
    ("fruitcans", "Take the object farthest back on the table and drop it in the bowl.", "in strawberry bowl"),
    ("textkitchen", "Counting from the left, put the second thing into the one on the far right.", "in soda_can@right bowl"),
    ("textblocks", "Of the three blocks, take the one farthest back and set it in front of the one nearest you.", "front cube@green cube@red"),
    ("scan45", "Lift whatever is sitting on top of the farthest-back object.", "lift small_white_object"),
    ("scan55", "See the thing farthest back? Push it about 5 cm toward yourself.", "moved second_from_left_yellow_object back 0.05"),
    # voice 3: very polite, indirect speaker
    ("kitchen", "Would you mind terribly placing the tomato soup can in the bowl? Thank you.", "in tomato_soup_can bowl"),
    ("pantry", "When you have a moment, I'd be grateful if the marker could end up to the left of the foam brick.", "left large_marker foam_brick"),
    ("mugbowl", "Might I ask you to nudge the bowl about two inches to the right? Much appreciated.", "moved bowl right 0.0508"),
    ("fruitcans", "If it's no bother, could the Rubik's cube perhaps sit between the strawberry and the potted meat tin?", "between rubiks_cube strawberry potted_meat_can"),
    ("textkitchen", "Could I trouble you to lift the mug up off the table for a moment? Thanks ever so much.", "lift mug"),
    ("textblocks", "Whenever it's convenient for you, would you please swap the red cube and the green cube? Thank you kindly.", "swapped cube@red cube@green"),
    ("scan45", "I'd be much obliged if the small white object could come off the big white object and rest on the table instead.", "table small_white_object"),
    ("scan55", "I hate to be a nuisance, but do you think the tall white can could go into the white bowl?", "in tall_white_can white_bowl"),
    # voice 4: corrects themselves mid-message
    ("kitchen", "Put the mug behind the bowl -- wait, no, in front of it.", "front mug bowl"),
    ("pantry", "Grab the foam brick, uh, I mean the Rubik's cube, and set it on the potted meat can.", "on rubiks_cube potted_meat_can"),
    ("mugbowl", "Slide the mug forward ten centimetres, sorry, make that fifteen.", "moved mug forward 0.15"),
    ("fruitcans", "Drop the banana in the bowl -- hold on, not the banana, the apple.", "refuse"),
    ("textkitchen", "Move the right soda can, er, the left one I mean, over next to the mug.", "next soda_can@left mug"),
    ("textblocks", "Green cube to the left of the plate. No, to the right, sorry.", "right cube@green plate"),
    ("scan45", "Take the right white can off the flat box and put it next to the red can, actually make that next to the left tall white can.", "next right_white_can left_tall_white_can"),
    ("scan55", "Push the blue box five centimetres to the left. Hang on, I meant the red box, not the blue one.", "moved red_box left 0.05"),
    # voice 5: robotics engineer, technical phrasing (x forward, y left)
    ("kitchen", "Translate cracker_box +8 cm in y, then return to home configuration.", "moved cracker_box left 0.08; home"),
    ("pantry", "Execute a pick on the mustard bottle and hold at lift height; no place.", "lift mustard_bottle"),
    ("mugbowl", "Clear the bowl out of the workspace, then place the mug at the bowl's initial pose.", "aside bowl; spot mug bowl"),
    ("fruitcans", "Apply a +0.04 m x-offset to the potted meat can via a push, no grasp required.", "moved potted_meat_can forward 0.04"),
    ("textkitchen", "Pick the right soda can and place it with clearance on the -y side of the cereal box.", "right soda_can@right cereal_box"),
    ("textblocks", "Sequence: place the red cube on the plate, then place the blue cube at the red cube's original pose.", "on cube@red plate; spot cube@blue cube@red"),
    ("scan45", "Red can is non-graspable at 10 cm min width, so do a planar push, +6 cm in y.", "moved red_can left 0.06"),
    ("scan55", "Grasp the small white object and place it inside the white bowl frame.", "in small_white_object white_bowl"),
    # voice 6: mixed multi-step tasks and requests the robot must decline
    ("kitchen", "Put the mug in the bowl, then move the soup can next to the cracker box, and after that head back home.", "in mug bowl; next tomato_soup_can cracker_box; home"),
    ("pantry", "Can you unscrew the mustard cap and squirt some on the foam brick?", "refuse"),
    ("mugbowl", "pour the mug out into the bowl", "refuse"),
    ("fruitcans", "First set the strawberry on the Rubik's cube, then slide the soup can 5 cm forward.", "on strawberry rubiks_cube; moved tomato_soup_can forward 0.05"),
    ("textkitchen", "Just grab the red can, would you?", "refuse"),
    ("textblocks", "Stack the blue cube on the red one, put the green one on the plate, then go home.", "on cube@blue cube@red; on cube@green plate; home"),
    ("scan45", "Pick up the red box and put it on the big white object.", "refuse"),
    ("scan55", "Toss the tennis ball into the white bowl.", "refuse"),
]
