"""Blind held-out command sentences written on 2026-11-29, fifth batch (``--set heldout22``).

Written at 15:18 UTC by a helper that read nothing of the repository (only the scenes' object lists
in the robot's frame, the goal words and a brief of six voices: a tired rambler, a streamer talking
to their chat, an instruction-manual writer, things named by use or resemblance, directions from the
speaker's own body, multi-step tasks mixed with requests to decline), added verbatim after every
other planner change of that session (held-out 20 and 21 fixed, "nearest you" from the base).
Measured with ``--plans``: 15/48 at d15e3d9 (the session's start) and 15/48 at f08455f: none of the
session's fixes reached it.
"""
from __future__ import annotations

HELDOUT22: list[tuple[str, str, str]] = [
    # voice 1: tired person late at night, rambling before the point
    ("kitchen", "so I was gonna do the dishes like three hours ago and then I fell into this octopus documentary, they have three hearts, did you know that, three... anyway. the mug. can you put it in the bowl please", "in mug bowl"),
    ("pantry", "mm, the foam brick, the red one, I keep thinking it's a real brick every time I walk past which says a lot about how tired I am, but yeah, set it down next to the mustard would you", "next foam_brick mustard_bottle"),
    ("mugbowl", "you know what, forget the bowl, I was going to say move the bowl but honestly no, just... push the mug forward, ten centimetres or so, that's it, that's all I want", "moved mug forward 0.1"),
    ("fruitcans", "the banana's been sitting there since Tuesday, or maybe Wednesday, I've lost track of the week entirely, um, stick it on the left side of the bowl I guess", "left banana bowl"),
    ("textkitchen", "that cereal box is kind of in the way of, well, everything, and I don't even know why I bought that cereal, nobody in this house eats it... just shove it out of the way", "aside cereal_box"),
    ("textblocks", "okay so the blocks, right, my kid was building a tower earlier and it all fell over and there were tears, so many tears, and, uh, where was I. the blue one. put the blue cube on the plate", "on cube@blue plate"),
    ("scan45", "the red can, which I keep wanting to call a paint tin even though it obviously isn't one, it's sort of sticking out, hm, or I'm imagining it... pull it back about five centimetres", "moved red_can back 0.05"),
    ("scan55", "I swear that big white object was somewhere sensible this morning, no wait, that was yesterday, the days are blurring... it's sitting on the small blue object now, just get it down onto the table", "table big_white_object"),

    # voice 2: streamer talking to chat
    ("kitchen", "chat, watch this. okay robot, pick up the banana. LET'S GOOO", "lift banana"),
    ("pantry", "alright alright, chat's been spamming 'rubik' for five minutes straight so fine, robot, put the Rubik's cube in front of the mustard. clip that", "front rubiks_cube mustard_bottle"),
    ("mugbowl", "yo yo yo we're back! someone in chat said it can't swap the mug and the bowl. robot, swap 'em. prove them wrong", "swapped mug bowl"),
    ("fruitcans", "mods pin this, the robot is about to slide the soup can back five centimetres. okay robot, go go go", "moved tomato_soup_can back 0.05"),
    ("textkitchen", "okay robot, the left soda can, yeah chat, the LEFT one, stick it in front of the cereal box. for the viewers", "front soda_can@left cereal_box"),
    ("textblocks", "hype moment chat, hype moment. robot: green cube goes between the red cube and the blue cube. if this works I'm doing a giveaway", "between cube@green cube@red cube@blue"),
    ("scan45", "guys this is a real scan so it's basically hard mode. robot, grab the small white object for me. come onnnn", "lift small_white_object"),
    ("scan55", "chat wants to see it lift the blue box, lmao okay, robot, lift the blue box, let's see what happens", "refuse"),

    # voice 3: instruction-manual writer
    ("kitchen", "Step 1: Locate the tomato soup can. Step 2: Place it to the right of the cracker box.", "right tomato_soup_can cracker_box"),
    ("pantry", "Ensure that the large marker is positioned directly in front of the potted meat can. Note: Do not disturb the remaining items.", "front large_marker potted_meat_can"),
    ("mugbowl", "Note: The mug is to be stored inside the bowl when not in use. Perform this storage procedure now.", "in mug bowl"),
    ("fruitcans", "Step 1: Identify the Rubik's cube. Step 2: Transfer the cube into the bowl. Step 3: Return the arm to its home position.", "in rubiks_cube bowl; home"),
    ("textkitchen", "Step 1: Locate the mug. Step 2: Position the mug behind the bowl, that is, on the side of the bowl farther from the robot.", "behind mug bowl"),
    ("textblocks", "Ensure that the red cube is placed adjacent to the green cube. Caution: The blue cube must remain in its current position.", "next cube@red cube@green"),
    ("scan45", "Step 1: Remove the white can currently resting on top of the flat white box. Step 2: Set it down directly on the table surface.", "table right_white_can"),
    ("scan55", "Procedure: Grasp the small white object. Place it on the table to the left of the orange cylinder.", "left small_white_object orange_cylinder"),

    # voice 4: names things by use or resemblance
    ("kitchen", "Could you put the thing I drink my morning coffee out of right beside the cheesy cracker box?", "next mug cracker_box"),
    ("kitchen", "The red and white tin, the stuff you heat up when you've got a cold, nudge it a couple of inches further away.", "moved tomato_soup_can forward 0.0508"),
    ("pantry", "Swap the Spam tin with the twisty puzzle cube, please.", "swapped potted_meat_can rubiks_cube"),
    ("pantry", "That bottle of yellow stuff you squirt on hot dogs, pick it up for me.", "lift mustard_bottle"),
    ("fruitcans", "Set the little red fruit down right in front of the Spam tin.", "front strawberry potted_meat_can"),
    ("fruitcans", "The colourful cube you twist until all the sides match, slide that five centimetres to the left.", "moved rubiks_cube left 0.05"),
    ("mugbowl", "Put the coffee cup in front of the dish you'd eat your cereal from.", "front mug bowl"),
    ("textkitchen", "Push the box the breakfast flakes come in about 10 cm further away from the robot.", "moved cereal_box forward 0.1"),

    # voice 5: directions from the speaker's own viewpoint
    ("textkitchen", "The soda can on my left, the one closer to me, put that in the bowl.", "in soda_can@left bowl"),
    ("textkitchen", "Take the soda can that's farther from me and stand it on my right side of the mug.", "right soda_can@right mug"),
    ("textblocks", "See the cube nearest to me? Slide it further away from me, say 4 cm.", "moved cube@red forward 0.04"),
    ("textblocks", "Whichever cube is way out on my left and farthest from me, set it on the plate over on my right.", "on cube@green plate"),
    ("scan45", "Of the two white cans, grab the one more to my right and put it down on my left of the red can.", "left right_white_can red_can"),
    ("scan55", "That white box over on my right, close to me, pull it three centimetres closer to me.", "moved white_box back 0.03"),
    ("scan55", "Put the tall white can next to the white bowl, the bowl is the far one over on my left.", "next tall_white_can white_bowl"),
    ("mugbowl", "Bring the mug over to my left so it ends up on my left of the bowl.", "left mug bowl"),

    # voice 6: mixed multi-step tasks and requests to decline
    ("kitchen", "Pour the soup into the bowl, would you?", "refuse"),
    ("pantry", "Pick up the tennis ball and set it by the marker.", "refuse"),
    ("mugbowl", "Open the drawer and put the mug inside it.", "refuse"),
    ("textblocks", "Just grab the cube.", "refuse"),
    ("scan45", "Lift the red box up off the table.", "refuse"),
    ("fruitcans", "Put the strawberry in the bowl, then slide the banana 5 cm to the right, and go back home afterwards.", "in strawberry bowl; moved banana right 0.05; home"),
    ("scan45", "Move the tall white can 10 cm to the left, and then put it back where it was.", "moved left_tall_white_can left 0.1; at left_tall_white_can"),
    ("scan55", "First get the small white object out of the way, then put the tall white can where the small white object used to be, then go home.", "aside small_white_object; spot tall_white_can small_white_object; home"),
]
