"""Blind held-out command sentences (heldout33), written 2026-11-30 01:20 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT33: list[tuple[str, str, str]] = [
    # voice 1: remote operator on a radio / walkie-talkie protocol
    ("kitchen", "Arm One, this is Control. Request you push the cracker box forward four centimetres, how copy? Over.", "moved cracker_box forward 0.04"),
    ("pantry", "Base to Franka: pick up the mustard bottle and set it down on the right of the Rubik's cube. Over.", "right mustard_bottle rubiks_cube"),
    ("mugbowl", "Franka, Franka, this is Tower. Mug goes into the bowl. Acknowledge. Over.", "in mug bowl"),
    ("fruitcans", "Control to arm, stand by for tasking... strawberry into the red bowl, then return to home position. Over and out.", "in strawberry bowl; home"),
    ("textkitchen", "Copy that, robot. Next task: cereal box, clear it out of the way. Over.", "aside cereal_box"),
    ("textblocks", "Base to robot, place the green cube on top of the plate, I say again, green cube on the plate. Over.", "on cube@green plate"),
    ("scan45", "Unit Two, Operations. Bring the tall white can back two inches toward yourself. Confirm. Over.", "moved left_tall_white_can back 0.0508"),
    ("scan55", "Robot, base here. Lift the white box and hold it. Over.", "lift white_box"),
    # voice 2: fast typist with typos, missing/swapped letters, no punctuation
    ("kitchen", "banaan in teh red bwol plz", "in banana bowl"),
    ("pantry", "slid the marekr to the lfet like 3 cm", "moved large_marker left 0.03"),
    ("mugbowl", "can u put the mug on the lefft side of teh bowl", "left mug bowl"),
    ("fruitcans", "swpa the rubiks cube and the soup cna", "swapped rubiks_cube tomato_soup_can"),
    ("textkitchen", "pik up the soda can", "refuse"),
    ("textblocks", "put teh red cueb inbetween the blue and grene ones", "between cube@red cube@blue cube@green"),
    ("scan45", "grab the small white thign and put it infront of the red can", "front small_white_object red_can"),
    ("scan55", "put the smal white objet in teh white bowl pls", "in small_white_object white_bowl"),
    # voice 3: cook / waiter using kitchen and serving language
    ("kitchen", "Get those crackers off my station, shove the box out of the way.", "aside cracker_box"),
    ("pantry", "Mustard goes alongside the potted meat tin, build me a little condiment station.", "next mustard_bottle potted_meat_can"),
    ("mugbowl", "Tuck the mug in behind the bowl, far side of the pass.", "behind mug bowl"),
    ("fruitcans", "Banana in the bowl, on the double, that's the garnish.", "in banana bowl"),
    ("textkitchen", "Run that mug over beside the bowl, table six is waiting.", "next mug bowl"),
    ("textblocks", "Blue cube onto the plate, like you're plating a dessert.", "on cube@blue plate"),
    ("scan45", "Eighty-six the red box, just get it off the line and out of the way.", "aside red_box"),
    ("scan55", "Red box, set it down next to the white bowl, family style.", "next red_box white_bowl"),
    # voice 4: request depends on the state of the scene
    ("kitchen", "Whichever of the banana and the mug is closer to me, push that one forward 4 cm.", "moved mug forward 0.04"),
    ("pantry", "If the foam brick is to the left of the Rubik's cube, put the brick behind the cube; otherwise just lift it.", "behind foam_brick rubiks_cube"),
    ("mugbowl", "Only if the mug isn't already on the right side of the bowl, move it there. If it is, just send the arm home.", "home"),
    ("fruitcans", "Take whichever fruit is farther from the bowl and drop it in the bowl.", "in strawberry bowl"),
    ("textkitchen", "Of the two soda cans, the one farther away from the mug goes in the bowl.", "in soda_can@left bowl"),
    ("textblocks", "Whichever cube sits nearest the plate, slide it 3 cm to the right.", "moved cube@red right 0.03"),
    ("scan45", "If the small white object is still sitting on top of the big white object, take it off and put it on the table.", "table small_white_object"),
    ("scan55", "Between the white box and the red box, the one that's farther from me should get pushed 5 cm to the left.", "moved red_box left 0.05"),
    # voice 5: describes the wanted result instead of the action
    ("kitchen", "When you're finished I want the soup can sitting to the right of the cracker box.", "right tomato_soup_can cracker_box"),
    ("pantry", "The end state I'm after: marker lying in front of the mustard.", "front large_marker mustard_bottle"),
    ("mugbowl", "I'd like the mug and the bowl to have traded places.", "swapped mug bowl"),
    ("fruitcans", "I want the Rubik's cube to end up where the soup can was, so the can has to be out of the way first.", "aside tomato_soup_can; spot rubiks_cube tomato_soup_can"),
    ("textkitchen", "Final picture: the right-hand soda can sitting inside the bowl.", "in soda_can@right bowl"),
    ("textblocks", "At the end the green cube should be on the right of the red one.", "right cube@green cube@red"),
    ("scan45", "Once you're done, the tall white can should be standing behind the red box.", "behind left_tall_white_can red_box"),
    ("scan55", "Nothing on top of the green box anymore, that tall white can belongs on the table.", "table tall_white_can"),
    # voice 6: mixed multi-step tasks and requests the robot must decline
    ("kitchen", "Pour the tomato soup into the red bowl.", "refuse"),
    ("pantry", "Take the Rubik's cube over to the left of the mustard, then nudge the foam brick back 2 cm, and after that go home.", "left rubiks_cube mustard_bottle; moved foam_brick back 0.02; home"),
    ("mugbowl", "Grab the banana and drop it in the bowl next to the mug.", "refuse"),
    ("fruitcans", "Put the strawberry in the bowl, then take it back out and return it to where it was.", "in strawberry bowl; at strawberry"),
    ("textkitchen", "Move the mug out of the way, then put the left soda can where the mug was.", "aside mug; spot soda_can@left mug"),
    ("textblocks", "Lift the plate up off the table for me.", "refuse"),
    ("scan45", "Pick up the red can and put it on the big white object.", "refuse"),
    ("scan55", "Open the blue box and check what's inside.", "refuse"),
]
