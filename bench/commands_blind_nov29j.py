"""Blind held-out command sentences (heldout27), written 2026-11-29 19:50 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT27: list[tuple[str, str, str]] = [
    # voice 1: young gamer using internet slang
    ("kitchen", "yo toss the banana in the bowl no cap", "in banana bowl"),
    ("pantry", "ngl that rubik's cube would look way better on the left side of the mustard lol", "left rubiks_cube mustard_bottle"),
    ("textblocks", "bruh just grab the green cube real quick", "lift cube@green"),
    ("scan55", "ok so the tall white can?? slide it like 10 cm to the right, ez", "moved tall_white_can right 0.10"),
    ("fruitcans", "lowkey the strawberry needs to be chillin next to the banana fr fr", "next strawberry banana"),
    ("mugbowl", "mug goes in the bowl, let's gooo", "in mug bowl"),
    ("textkitchen", "can u swap the mug and the cereal box lmao", "swapped mug cereal_box"),
    ("scan45", "that small white thing sitting on top of the big one, yeet it onto the flat white box pls", "on small_white_object flat_white_box"),
    # voice 2: scientist / engineer giving precise technical instructions
    ("kitchen", "Translate the tomato soup can 5 cm along the base frame's negative x axis, i.e. toward the robot.", "moved tomato_soup_can back 0.05"),
    ("pantry", "Displace the foam brick laterally by 0.08 m in the robot's negative y direction.", "moved foam_brick right 0.08"),
    ("fruitcans", "Relocate the potted meat tin to a position posterior to the bowl.", "behind potted_meat_can bowl"),
    ("textblocks", "Elevate the blue cube off the tabletop surface and maintain the grasp.", "lift cube@blue"),
    ("scan55", "Position the small white object such that it is interposed between the white bowl and the blue box.", "between small_white_object white_bowl blue_box"),
    ("scan45", "Apply a planar displacement of +4 cm along the y axis to the tall white can.", "moved left_tall_white_can left 0.04"),
    ("mugbowl", "Deposit the mug on the table anterior to the bowl, that is, at a reduced radial distance from the manipulator base.", "front mug bowl"),
    ("textkitchen", "Transpose the positions of the two soda cans.", "swapped soda_can@left soda_can@right"),
    # voice 3: stating own plans or needs rather than giving orders
    ("kitchen", "When I come back I'd like to find the mug sitting right beside the cracker box.", "next mug cracker_box"),
    ("pantry", "I'm going to be writing on the whiteboard later, so I'll want that marker about ten centimetres closer to me.", "moved large_marker back 0.10"),
    ("fruitcans", "I'll be working in the spot where the Rubik's cube is, so it needs to be out of my way.", "aside rubiks_cube"),
    ("mugbowl", "What I'm hoping for is the bowl ending up on the right-hand side of the mug.", "right bowl mug"),
    ("textblocks", "For the photo I'm setting up, the red cube has to be sitting on the plate.", "on cube@red plate"),
    ("scan55", "I'm going to need the white bowl a little farther away from me, maybe five centimetres.", "moved white_bowl forward 0.05"),
    ("textkitchen", "Ideally the right-hand soda can ends up in the bowl, I'm collecting the cans there.", "in soda_can@right bowl"),
    ("scan45", "For my demo the right white can should be off that flat box and standing on the table next to the red can.", "next right_white_can red_can"),
    # voice 4: regional dialects (Scottish, Australian, Southern US, Irish)
    ("textblocks", "Och, gie yon wee green cube a shove tae the left, aboot five centimetres like.", "moved cube@green left 0.05"),
    ("kitchen", "Oi mate, reckon you could plonk the soup tin down next to the Cheez-It box?", "next tomato_soup_can cracker_box"),
    ("fruitcans", "Y'all mind settin' that little strawberry down in the bowl for me, sugar?", "in strawberry bowl"),
    ("pantry", "Ah go on, would ya lift the little foam brick up for me there.", "lift foam_brick"),
    ("textkitchen", "Cannae see a thing past that cereal box, shift it oot the road, would ye?", "aside cereal_box"),
    ("scan55", "Give the green box a wee bit of a nudge towards me, yeah? Bout four centimetres, no worries.", "moved green_box back 0.04"),
    ("mugbowl", "Well I'll be, that mug's plumb in the way. Carry it on over behind the bowl, would ya?", "behind mug bowl"),
    ("scan45", "Sure put the tall white can over beside the red box there, good man yourself.", "next left_tall_white_can red_box"),
    # voice 5: corrects themselves mid-request / changes their mind
    ("kitchen", "Put the mug behind the cracker box, hmm, no, make that in front of it.", "front mug cracker_box"),
    ("pantry", "Nudge the marker left by three... scratch that, by six centimetres.", "moved large_marker left 0.06"),
    ("textblocks", "Pick up the blue cube, hang on, actually the red one.", "lift cube@red"),
    ("fruitcans", "Move the soup can back two inches, no wait, forward two inches.", "moved tomato_soup_can forward 0.0508"),
    ("mugbowl", "Okay, bowl to the left of the mug. Er, I said that backwards, I meant the mug to the left of the bowl.", "left mug bowl"),
    ("scan55", "Could you put the small white object in the white bowl? Oh sorry, not the bowl, onto the green box.", "on small_white_object green_box"),
    ("textkitchen", "Take the left soda can and put it, uh, by the mug. No, between the mug and the cereal box.", "between soda_can@left mug cereal_box"),
    ("scan45", "Push the red box forward, uh, backward I mean, like 6 cm.", "moved red_box back 0.06"),
    # voice 6: mixed multi-step tasks and requests the robot must decline
    ("kitchen", "First put the banana in the bowl, then send the arm back home.", "in banana bowl; home"),
    ("pantry", "Lift the foam brick and set it behind the mustard bottle, slide the Rubik's cube five centimetres left, then park the arm.", "behind foam_brick mustard_bottle; moved rubiks_cube left 0.05; home"),
    ("kitchen", "Pour the tomato soup into the bowl.", "refuse"),
    ("textblocks", "Put the cube on the plate.", "refuse"),
    ("scan55", "Pick up the red box and hold it in the air.", "refuse"),
    ("fruitcans", "Put the apple next to the banana.", "refuse"),
    ("textkitchen", "Grab the red soda can.", "refuse"),
    ("scan45", "Open the flat white box and look inside.", "refuse"),
]
