"""Blind held-out command sentences (heldout30), written 2026-11-29 22:24 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT30: list[tuple[str, str, str]] = [
    # voice 1: rambling storyteller, the one request buried in chat about their day
    ("kitchen", "Ugh, what a morning, the bus was late, my coffee went cold before I even sat down, and now I just want this table looking tidy. Could you set the mug down inside the bowl for me?", "in mug bowl"),
    ("fruitcans", "You know, I was at the farmers' market on Saturday and they had these gorgeous strawberries, nothing like this plastic one, ha. Anyway, pop the strawberry into the bowl, would you?", "in strawberry bowl"),
    ("textblocks", "My nephew was over all weekend building towers, and he always insists the red block goes on top of the green one, says it's a volcano or something. Do that for me so I can send him a picture?", "on cube@red cube@green"),
    ("pantry", "I was clearing out the cupboard earlier and found, I kid you not, six of those blue tins, who even buys that much. Right, where was I, oh yes, put the tin over on the left side of the mustard.", "left potted_meat_can mustard_bottle"),
    ("scan55", "We had a team lunch today and of course somebody left their things scattered all over, typical. Well, the tall white can, would you mind putting it in the white bowl?", "in tall_white_can white_bowl"),
    ("textkitchen", "My flatmate drinks these sodas like water and just leaves them lying around, always right at the edge too, drives me mad. The one furthest to the left, could you stand it next to the bowl?", "next soda_can@left bowl"),
    ("scan45", "I spent the whole afternoon on hold with the insurance people, don't even ask. Oh, before I forget, just lift the tall white can up for a second, I want to see it properly.", "lift left_tall_white_can"),
    ("mugbowl", "It was my mum's birthday yesterday, we had cake and far too much tea, and that mug is still sitting there from it. If you could bring it round in front of the bowl, that'd be lovely.", "front mug bowl"),

    # voice 2: rough everyday measures and mixed units
    ("kitchen", "Nudge the soup can a couple of inches to the left.", "moved tomato_soup_can left 0.0508"),
    ("pantry", "The Rubik's cube, slide it forward, oh, roughly three inches or thereabouts.", "moved rubiks_cube forward 0.0762"),
    ("mugbowl", "Pull the bowl about half a foot back towards me.", "moved bowl back 0.1524"),
    ("fruitcans", "Could you push the banana 10 centimetres or so to the left?", "moved banana left 0.1"),
    ("textblocks", "Green cube: shift it maybe an inch and a half further away from you.", "moved cube@green forward 0.0381"),
    ("scan45", "Slide the red can to the left by about three fingers' width.", "moved red_can left 0.06"),
    ("scan55", "Can you bring the blue box a smidge closer to me? Just a tiny bit, like three centimetres.", "moved blue_box back 0.03"),
    ("textkitchen", "Push the bowl rightwards by about the width of a hand.", "moved bowl right 0.1"),

    # voice 3: gamer framing it as a game or challenge
    ("fruitcans", "Achievement unlocked if the Rubik's cube lands in the bowl. Go!", "in rubiks_cube bowl"),
    ("textblocks", "Level 3, tower builder: blue cube on top of the red cube. Clock's ticking.", "on cube@blue cube@red"),
    ("kitchen", "Speedrun category: banana and soup can trade places, any percent, no fumbles allowed.", "swapped banana tomato_soup_can"),
    ("pantry", "Mini-game time! Park the marker right beside the foam brick. Three, two, one...", "next large_marker foam_brick"),
    ("scan55", "Side quest for you: the small white object goes in the white bowl. Reward is my eternal gratitude.", "in small_white_object white_bowl"),
    ("scan45", "Challenge mode engaged. Objective: the right white can has to end up in front of the red can.", "front right_white_can red_can"),
    ("mugbowl", "Final round, winner takes all: mug in the bowl. Don't choke!", "in mug bowl"),
    ("textkitchen", "Co-op mission, player two: sink the soda can on the right into the bowl for the high score.", "in soda_can@right bowl"),

    # voice 4: a wish about the scene or a problem to fix
    ("kitchen", "The cracker box is cluttering up the middle of the table, I need it out of there.", "aside cracker_box"),
    ("pantry", "That foam brick keeps getting in my way.", "aside foam_brick"),
    ("mugbowl", "I'd like the mug on the left side of the bowl for once.", "left mug bowl"),
    ("fruitcans", "The strawberry looks so lonely way out at the back; I'd like it sitting right beside the soup can.", "next strawberry tomato_soup_can"),
    ("textblocks", "Those blocks are far too spread out. I want the green one sitting right next to the red one.", "next cube@green cube@red"),
    ("scan55", "It bothers me that the tall white can is perched up there; it would look better standing beside the white bowl.", "next tall_white_can white_bowl"),
    ("scan45", "The small white object shouldn't be stacked on top of the big one, it belongs down on the table.", "table small_white_object"),
    ("textkitchen", "Honestly the mug is in a silly spot, I'd rather have it in front of the cereal box.", "front mug cereal_box"),

    # voice 5: terse text-message / note style
    ("fruitcans", "banana->bowl ty", "in banana bowl"),
    ("pantry", "brick on top of rubiks pls", "on foam_brick rubiks_cube"),
    ("kitchen", "soup can in front of crackers", "front tomato_soup_can cracker_box"),
    ("textblocks", "red cube onto plate thx", "on cube@red plate"),
    ("scan55", "ok all done. arm back home", "home"),
    ("mugbowl", "mug 10cm L", "moved mug left 0.1"),
    ("scan45", "tall wht can -> L of red can", "left left_tall_white_can red_can"),
    ("textkitchen", "open cereal box pls", "refuse"),

    # voice 6: mixed -- two- and three-step tasks, and requests the robot must decline
    ("kitchen", "Put the banana in the bowl, then slide the mug about 5 cm toward me, and after that head back home.", "in banana bowl; moved mug back 0.05; home"),
    ("fruitcans", "First swap the soup can and the Rubik's cube, and once that's done drop the strawberry in the bowl.", "swapped tomato_soup_can rubiks_cube; in strawberry bowl"),
    ("textblocks", "Stack the green cube on the blue one, then move the red cube to where the green one was sitting.", "on cube@green cube@blue; spot cube@red cube@green"),
    ("kitchen", "Pour the soup into the bowl for me.", "refuse"),
    ("pantry", "Grab the banana and lay it next to the mustard.", "refuse"),
    ("textkitchen", "Hand me the soda can.", "refuse"),
    ("scan55", "Lift the white bowl up off the table.", "refuse"),
    ("scan45", "Pick up the red box and hold it in the air.", "refuse"),
]
