"""Blind held-out command sentences (heldout31), written 2026-11-29 23:12 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT31: list[tuple[str, str, str]] = [
    # voice 1: a parent talking half to their toddler and half to the robot
    ("kitchen", "Look sweetie, see the yellow banana? The robot's gonna put it in the red bowl. Okay robot, banana in the bowl, please.", "in banana bowl"),
    ("pantry", "Ooh, which one's the Rubik's cube, baby? That's right, the colourful one! Robot, can you pick up the Rubik's cube for us?", "lift rubiks_cube"),
    ("mugbowl", "Mummy's cup is going for a ride! Robot, put the mug in the bowl. Wave bye-bye to the mug, sweetheart.", "in mug bowl"),
    ("fruitcans", "Strawberry! Can you say strawberry? Clever boy. Now robot, put the strawberry next to the banana please.", "next strawberry banana"),
    ("textkitchen", "Hands down, let the robot do it. Robot, slide the bowl ten centimetres to the right. Ten, like all your fingers!", "moved bowl right 0.10"),
    ("textblocks", "Which block do you like, the blue one? Okay, blue it is. Robot, put the blue cube on the plate. Yaaay!", "on cube@blue plate"),
    ("scan45", "We can't see anything behind that red box, can we, bug? Robot, move the red box out of the way please.", "aside red_box"),
    ("scan55", "Where's the white box? There it is! Robot, put the white box next to the white bowl, and then we'll have snack.", "next white_box white_bowl"),

    # voice 2: naming things by what they look like, not by the list's words
    ("kitchen", "Take the cup with the handle and set it down beside the tall skinny carton.", "next mug cracker_box"),
    ("pantry", "That squishy little red block, put it right up next to the squeeze bottle.", "next foam_brick mustard_bottle"),
    ("mugbowl", "Could you just pick up the thing with the handle?", "lift mug"),
    ("fruitcans", "Stand the little red-and-white tin on the left side of the curved yellow thing.", "left tomato_soup_can banana"),
    ("textkitchen", "The red thing with the handle, stand it behind the tall flat package.", "behind mug cereal_box"),
    ("textblocks", "Slide the big round white dish forward about five centimetres.", "moved plate forward 0.05"),
    ("scan45", "Nudge the skinny pale cylinder, the one that stands right on the table, two inches to the left.", "moved left_tall_white_can left 0.0508"),
    ("scan55", "Take the tall pale can that's perched on the flat tray and drop it into the deep round dish.", "in tall_white_can white_bowl"),

    # voice 3: steps said out of order with before/after/first-but
    ("kitchen", "Before you put the soup can in front of the cracker box, push the bowl 5 cm to the right.", "moved bowl right 0.05; front tomato_soup_can cracker_box"),
    ("pantry", "Lay the marker down to the left of the mustard bottle, but first get the foam brick out of the way.", "aside foam_brick; left large_marker mustard_bottle"),
    ("mugbowl", "Go home at the end, but before that put the mug behind the bowl, and even before that slide the bowl 10 cm back toward the robot.", "moved bowl back 0.10; behind mug bowl; home"),
    ("fruitcans", "The strawberry goes in the bowl, but not until you've moved the soup can out of the way.", "aside tomato_soup_can; in strawberry bowl"),
    ("textkitchen", "Swap the mug and the cereal box. Oh, do that after you've put the left soda can next to the bowl.", "next soda_can@left bowl; swapped mug cereal_box"),
    ("textblocks", "Put the red cube on the plate second; first, nudge the green cube 3 cm forward.", "moved cube@green forward 0.03; on cube@red plate"),
    ("scan45", "After you go home... no wait, before you go home, take the small white object off the big white object and put it on the table.", "table small_white_object; home"),
    ("scan55", "Put the white box where the red box was, but before that, move the red box out of the way.", "aside red_box; spot white_box red_box"),

    # voice 4: conditions on the scene
    ("kitchen", "If the mug is to the right of the bowl, drop the soup can into the bowl; if it isn't, just go home.", "in tomato_soup_can bowl"),
    ("pantry", "If the mustard is nearer to the robot than the foam brick, nudge the mustard 5 cm back; if not, nudge it 5 cm forward.", "moved mustard_bottle forward 0.05"),
    ("mugbowl", "Assuming the bowl is to the left of the mug, swap them. If it's not, leave everything alone.", "swapped bowl mug"),
    ("fruitcans", "Is there a pear out there? If so, it goes in the bowl. If not, put the Rubik's cube in the bowl instead.", "in rubiks_cube bowl"),
    ("textkitchen", "Put the mug in the bowl, unless the cereal box is the nearest thing to the robot; in that case just slide the cereal box 5 cm to the left.", "moved cereal_box left 0.05"),
    ("textblocks", "If the blue cube sits between the red one and the green one, lift it up; otherwise put it on the plate.", "lift cube@blue"),
    ("scan45", "In case the red box is to the right of the red can, put the red box behind the tall white can; otherwise put it in front of the red can.", "behind red_box left_tall_white_can"),
    ("scan55", "When the tall white can is standing on the green box, take it off and put it on the table; if it isn't, go home.", "table tall_white_can"),

    # voice 5: stiff legalese or bureaucratic English
    ("kitchen", "The operator hereby requests that the banana be relocated to a position immediately adjacent to the mug.", "next banana mug"),
    ("pantry", "Pursuant to the workspace tidiness policy, the large marker shall be conveyed to a location situated between the potted meat can and the Rubik's cube.", "between large_marker potted_meat_can rubiks_cube"),
    ("mugbowl", "Notwithstanding any prior instructions, the mug is to be displaced a distance of eight centimetres in the forward direction, i.e. away from the robot.", "moved mug forward 0.08"),
    ("fruitcans", "It is hereby requested that the banana first be removed to a location where it presents no obstruction, and that the potted meat can thereafter be placed at the position the banana formerly occupied.", "aside banana; spot potted_meat_can banana"),
    ("textkitchen", "The undersigned formally requests that the contents of the mug be poured into the bowl at the earliest convenience.", "refuse"),
    ("textblocks", "Kindly effect the transfer of the green cube to a position directly behind the red cube, 'behind' being understood as farther from the robot.", "behind cube@green cube@red"),
    ("scan45", "Be advised that the small white object is to be removed from atop the big white object and deposited adjacent to the red box.", "next small_white_object red_box"),
    ("scan55", "The white bowl shall, upon receipt of this instruction, be relocated to the left-hand side of the orange cylinder.", "left white_bowl orange_cylinder"),

    # voice 6: mixed: two- and three-step tasks, and requests the robot must decline
    ("kitchen", "Grab the strawberry and drop it in the mug for me.", "refuse"),
    ("pantry", "Three things: Rubik's cube behind the mustard bottle, foam brick 4 cm to the right, then go home.", "behind rubiks_cube mustard_bottle; moved foam_brick right 0.04; home"),
    ("mugbowl", "Balance the mug upside down on the rim of the bowl.", "refuse"),
    ("fruitcans", "Swap the banana and the strawberry, and then put the Rubik's cube behind the potted meat can.", "swapped banana strawberry; behind rubiks_cube potted_meat_can"),
    ("textkitchen", "Put the red soda can next to the bowl, would you.", "refuse"),
    ("textblocks", "Lift the plate up off the table.", "refuse"),
    ("scan45", "Pick up the red can and hold it in the air.", "refuse"),
    ("scan55", "Push the orange cylinder 5 cm left, put the small white object in the white bowl, then head home.", "moved orange_cylinder left 0.05; in small_white_object white_bowl; home"),
]
