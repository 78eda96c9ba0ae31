"""Blind held-out command sentences (heldout23), written 2026-11-29 17:15 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT23: list[tuple[str, str, str]] = [
    # voice 1: exasperated person who has had to repeat themselves
    ("kitchen", "For the LAST time: the banana goes IN the bowl. Not beside it, not near it. In it.", "in banana bowl"),
    ("pantry", "Ugh. Third time I'm saying this. Pick up the Rubik's cube. Just lift it. That's all I want.", "lift rubiks_cube"),
    ("mugbowl", "Damn it, the mug goes on the LEFT of the bowl. Your left! We're facing the same way, it's the same left, just do it.", "left mug bowl"),
    ("fruitcans", "*sigh* Okay. Slowly. Slide the potted meat tin forward ten centimetres. TEN. Not two, not twenty.", "moved potted_meat_can forward 0.10"),
    ("textkitchen", "No, no, no. I keep telling you: cereal box BEHIND the bowl. Behind means farther away from you. Please.", "behind cereal_box bowl"),
    ("textblocks", "How many times do I have to ask? Green cube. On the plate. ON it. Before I lose my mind.", "on cube@green plate"),
    ("scan45", "Seriously? I said push the red box five centimetres to the RIGHT. Don't try to pick it up, just shove it over.", "moved red_box right 0.05"),
    ("scan55", "Oh for crying out loud. The tall white can. Next to the white bowl. Why is that so hard?", "next tall_white_can white_bowl"),

    # voice 2: points things out first, then gives the order in a short follow-up
    ("kitchen", "See the soup can at the back, on the left? Grab it. Then set it down in front of the cracker box.", "front tomato_soup_can cracker_box"),
    ("pantry", "That black marker on the far right. Yep, the dry-erase one. Put it next to the mustard.", "next large_marker mustard_bottle"),
    ("mugbowl", "The bowl. Yeah, the red one out front. Push it back toward yourself, about four inches.", "moved bowl back 0.1016"),
    ("fruitcans", "There's a strawberry way at the back. Got it? Drop it into the bowl.", "in strawberry bowl"),
    ("textkitchen", "Look at the mug, over on the left by the cans. Lift it up and just hold it.", "lift mug"),
    ("textblocks", "Red cube. That's the one nearest you. Park it to the right of the plate.", "right cube@red plate"),
    ("scan45", "You see the tall white can on the left, just behind the red can? That one. Get it out of the way.", "aside left_tall_white_can"),
    ("scan55", "Small white object, far right, closest to you. The flat one. Nudge it forward five centimetres.", "moved small_white_object forward 0.05"),

    # voice 3: storyteller / game master narrating a little quest
    ("kitchen", "Hear ye! The humble soup can, weary of its lonely corner, must make the long pilgrimage across the table to rest beside the banana.", "next tomato_soup_can banana"),
    ("pantry", "Our hero, the little red foam brick, sets out from home on a quest to reach the lands that lie behind the great mustard bottle.", "behind foam_brick mustard_bottle"),
    ("mugbowl", "And so the mug, having wandered the table for many a day, comes at last to its bowl and settles down inside it.", "in mug bowl"),
    ("fruitcans", "Brave Sir Rubik, the many-coloured knight, is called to stand guard in the pass between the strawberry and the potted meat tin.", "between rubiks_cube strawberry potted_meat_can"),
    ("textkitchen", "Two crimson soda cans keep watch at the edge of the realm. The elder, who stands farthest to the left, is summoned to take a place beside the bowl.", "next soda_can@left bowl"),
    ("textblocks", "The blue cube and the green cube have long quarrelled over their lands. Let them trade places, and peace shall return to the kingdom of blocks.", "swapped cube@blue cube@green"),
    ("scan45", "Our tale is told and the deeds are done. Let the iron arm return to its resting place and sleep.", "home"),
    ("scan55", "The mighty orange cylinder, a great round stone across the road, must be shoved ten centimetres to the left so the caravan may pass.", "moved orange_cylinder left 0.10"),

    # voice 4: clock positions / rough directions from the robot's viewpoint, mixed with names
    ("kitchen", "The mug's out past your one o'clock, the thing farthest to your right. Bring it round to twelve and tuck it in just behind the cracker box.", "behind mug cracker_box"),
    ("pantry", "At about one o'clock, nearest you, there's a blue tin. Slide it two inches toward your nine.", "moved potted_meat_can left 0.0508"),
    ("mugbowl", "Bowl's dead ahead at twelve, mug's off around your one. Set the mug down on the bowl's six o'clock side, between the bowl and you.", "front mug bowl"),
    ("fruitcans", "The soup can over at your ten o'clock: grab it and bring it up to twelve, right behind the potted meat tin.", "behind tomato_soup_can potted_meat_can"),
    ("textkitchen", "Cereal box, roughly your eleven o'clock. Shove it five centimetres toward three o'clock.", "moved cereal_box right 0.05"),
    ("textblocks", "Green cube, the far one out toward ten o'clock. Put it on the nine o'clock side of the plate.", "left cube@green plate"),
    ("scan45", "That big red box around your one o'clock, pick it up and hold it up high for me.", "refuse"),
    ("scan55", "Two o'clock-ish, there's the big white object sitting on the blue thing. Put it in the white bowl at your twelve.", "in big_white_object white_bowl"),

    # voice 5: describes the wanted end state (past/perfect tense, wish), not an order
    ("kitchen", "The banana really belongs on the left side of the cracker box.", "left banana cracker_box"),
    ("pantry", "When I come back I'd like to find the potted meat sitting behind the Rubik's cube.", "behind potted_meat_can rubiks_cube"),
    ("mugbowl", "Ideally the mug would have been pushed about ten centimetres farther away from you.", "moved mug forward 0.10"),
    ("fruitcans", "It'd be nice if the strawberry and the banana had swapped places by now.", "swapped strawberry banana"),
    ("textkitchen", "What I'm picturing is the right-hand one of the two soda cans, sitting inside the bowl.", "in soda_can@right bowl"),
    ("textblocks", "In my head the green cube's been moved out of the way and the red cube is sitting exactly where the green one used to be.", "aside cube@green; spot cube@red cube@green"),
    ("scan45", "The small white object shouldn't be perched on that big white thing; it belongs down on the table.", "table small_white_object"),
    ("scan55", "By the end of this, the tall white can should be standing behind the white bowl.", "behind tall_white_can white_bowl"),

    # voice 6: mixed multi-step tasks and requests the robot must decline
    ("kitchen", "Pour the tomato soup into the red bowl for me.", "refuse"),
    ("pantry", "Move the Rubik's cube out of the way, put the foam brick where the cube was, and then go back to your home position.", "aside rubiks_cube; spot foam_brick rubiks_cube; home"),
    ("mugbowl", "Balance the mug upside down on the rim of the bowl.", "refuse"),
    ("fruitcans", "Put the banana in the bowl, then slide the soup can five centimetres back toward you.", "in banana bowl; moved tomato_soup_can back 0.05"),
    ("textkitchen", "Pick up the red soda can and set it next to the mug.", "refuse"),
    ("textblocks", "Take the yellow cube and put it on the plate.", "refuse"),
    ("scan45", "Grab the green bottle and stand it next to the red can.", "refuse"),
    ("scan55", "Take the small white object, lay it on the green box, and then head home.", "on small_white_object green_box; home"),
]
