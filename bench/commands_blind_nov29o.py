"""Blind held-out command sentences (heldout32), written 2026-11-29 23:14 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT32: list[tuple[str, str, str]] = [
    # voice 1: speaker whose first language puts the verb last / uses its own word order
    ("kitchen", "The banana into the bowl you put, please.", "in banana bowl"),
    ("pantry", "Marker, to the left of the mustard bottle, you are putting.", "left large_marker mustard_bottle"),
    ("mugbowl", "The mug on the left side of the bowl you set down.", "left mug bowl"),
    ("fruitcans", "Soup can, behind the Rubik's cube, you place it.", "behind tomato_soup_can rubiks_cube"),
    ("textkitchen", "The right soda can, behind the cereal box it must go.", "behind soda_can@right cereal_box"),
    ("textblocks", "Green cube on the plate you put, and after, the blue cube next to it.", "on cube@green plate; next cube@blue cube@green"),
    ("scan45", "From the big white thing the small white object you take, and on the table you put it.", "table small_white_object"),
    ("scan55", "Tall white can, from the green box down, on the table now putting.", "table tall_white_can"),
    # voice 2: capitals, headlines and labels
    ("kitchen", "SOUP CAN -> RIGHT OF CRACKER BOX. THEN HOME.", "right tomato_soup_can cracker_box; home"),
    ("pantry", "MUSTARD BOTTLE: FORWARD 5 CM", "moved mustard_bottle forward 0.05"),
    ("mugbowl", "URGENT - bowl in the way. Clear it aside.", "aside bowl"),
    ("fruitcans", "RUBIK'S CUBE >> BOWL. NOTHING ELSE.", "in rubiks_cube bowl"),
    ("textkitchen", "CEREAL BOX / NUDGE 2 INCHES LEFT", "moved cereal_box left 0.0508"),
    ("textblocks", "SWAP: RED CUBE <-> BLUE CUBE", "swapped cube@red cube@blue"),
    ("scan45", "JOB 1 - PICK UP LEFT TALL WHITE CAN AND HOLD IT", "lift left_tall_white_can"),
    ("scan55", "WHITE BOWL. 5 CM TO THE LEFT. DONE.", "moved white_bowl left 0.05"),
    # voice 3: picking objects by comparing them
    ("kitchen", "Whichever is closer to the bowl, the mug or the banana, that one goes to the left of the bowl.", "left mug bowl"),
    ("pantry", "Could you pick up the tallest thing on the table and just hold it?", "lift mustard_bottle"),
    ("mugbowl", "Put the smaller one into the bigger one.", "in mug bowl"),
    ("fruitcans", "Of the two fruits, the smaller one goes in the bowl.", "in strawberry bowl"),
    ("textkitchen", "Between the mug and the cereal box, take the smaller one and set it right next to the bowl.", "next mug bowl"),
    ("textblocks", "The cube that's nearest the plate - put it on the plate.", "on cube@red plate"),
    ("scan45", "Grab the taller of the two white cans and stand it to the left of the red can.", "left left_tall_white_can red_can"),
    ("scan55", "I want the smaller of the two white objects in the white bowl.", "in small_white_object white_bowl"),
    # voice 4: undo / redo within one message
    ("kitchen", "Move the mug 5 cm to the left. Hmm, actually, undo that.", "moved mug left 0.05; at mug"),
    ("pantry", "Stick the foam brick on top of the potted meat can, then take it off again and leave it where it was.", "on foam_brick potted_meat_can; at foam_brick"),
    ("mugbowl", "Lift the mug up... okay, now set it down again exactly where you found it.", "lift mug; at mug"),
    ("fruitcans", "Banana in the bowl first. Then the strawberry, same as you did with the banana.", "in banana bowl; in strawberry bowl"),
    ("textkitchen", "Drop the left soda can in the bowl - no wait, take it back out and put it back where it stood.", "in soda_can@left bowl; at soda_can@left"),
    ("textblocks", "Red cube on the blue cube. Ah, no, sorry, reverse that.", "on cube@red cube@blue; at cube@red"),
    ("scan45", "Push the red box 4 cm to the right, then undo it.", "moved red_box right 0.04; at red_box"),
    ("scan55", "First the tall white can into the white bowl, then take it out again and return it to its place on the green box.", "in tall_white_can white_bowl; at tall_white_can"),
    # voice 5: directions relative to other things or to the speaker
    ("kitchen", "Bring the soup can about 10 cm toward me.", "moved tomato_soup_can back 0.1"),
    ("pantry", "That blue tin of meat, put it closer to the mustard, just in front of it on my side.", "front potted_meat_can mustard_bottle"),
    ("mugbowl", "Could you slide the bowl away from me, maybe 5 centimetres?", "moved bowl forward 0.05"),
    ("fruitcans", "Take the Rubik's cube further from the soup can, over to the right of the potted meat can.", "right rubiks_cube potted_meat_can"),
    ("textkitchen", "The mug should be between me and the bowl.", "front mug bowl"),
    ("textblocks", "Green cube - bring it over to the plate so it's sitting right beside it.", "next cube@green plate"),
    ("scan45", "Small white object: off the big one, and down closer to me, in front of the red can.", "front small_white_object red_can"),
    ("scan55", "Carry the red box over to my left-hand side of the white bowl.", "left red_box white_bowl"),
    # voice 6: mixed multi-step tasks and requests that must be declined
    ("kitchen", "Pour the tomato soup into the bowl for me.", "refuse"),
    ("pantry", "Marker beside the foam brick, mustard bottle 3 cm to the right, and then back to home.", "next large_marker foam_brick; moved mustard_bottle right 0.03; home"),
    ("mugbowl", "Hand me the spoon that's in the mug.", "refuse"),
    ("fruitcans", "Three things: strawberry next to the potted meat can, soup can to the right of the Rubik's cube, then go home.", "next strawberry potted_meat_can; right tomato_soup_can rubiks_cube; home"),
    ("textkitchen", "Grab the soda can and drop it in the bowl.", "refuse"),
    ("textblocks", "Lift the plate off the table and keep holding it up.", "refuse"),
    ("scan45", "Pick the red can up, please.", "refuse"),
    ("scan55", "Move the yellow object next to the blue box.", "refuse"),
]
