"""Blind held-out command sentences written on 2026-11-26, second batch (``--set heldout15``).

Written by someone who never read the planner, its tests, the other sets or any file of the
repository (only the scenes' object lists and the goal words), added verbatim and measured
before any planner change for it.
"""

from __future__ import annotations

# Written on 2026-11-26 (15:32 UTC) as six kinds of people talk: a retired person new to robots (polite,
# wordy), a teenager/gamer, a chef giving quick orders, several steps in one message, objects named only by
# where they are, hedged requests and questions.
HELDOUT15: list[tuple[str, str, str]] = [
    # retired person who has never used a robot, very polite and wordy
    ("kitchen", "Good morning, dear robot. If it isn't too much trouble, would you kindly pick up the banana and place it gently into the bowl? Thank you ever so much.", "in banana bowl"),
    ("pantry", "Hello there, young fellow. I wonder if you would be so good as to lift the mustard bottle up for me, the yellow one in the middle. Much obliged, I'm sure.", "lift mustard_bottle"),
    ("mugbowl", "Excuse me, robot, would you please be so kind as to place the teapot into the bowl for me? Thank you, dear.", "refuse"),
    ("fruitcans", "Good afternoon. Might I trouble you to put the little strawberry into the bowl, please? And afterwards do go back to your resting position. Thank you kindly.", "in strawberry bowl; home"),
    ("textkitchen", "Hello. Would you be so kind as to place the white mug inside the white bowl, if you please? Thank you very much indeed.", "in mug bowl"),
    ("textblocks", "Good day to you. Would you kindly set the red cube down upon the white plate? I would be most grateful, thank you.", "on cube@right plate"),
    ("scan45", "Excuse me, robot, I hope I'm not bothering you. Could you please pick up the red can and just hold it up for me? Thank you so very much.", "lift red_can"),
    ("scan55", "Good evening. Now, would you be so kind as to take that tall white can and put it into the white bowl at the back, please? Thank you, that's lovely.", "in tall_white_can white_bowl"),
    # teenager / gamer
    ("kitchen", "yo put the mug next to the cracker box lol", "next mug cracker_box"),
    ("pantry", "grab the rubiks cube n put it behind the mustard thx", "behind rubiks_cube mustard_bottle"),
    ("mugbowl", "mug in bowl pls", "in mug bowl"),
    ("fruitcans", "move the soup can next 2 the banana ty", "next soup_can banana"),
    ("textkitchen", "grab the soda can thats furthest left n put it next to the bowl", "next soda_can@left bowl"),
    ("textblocks", "pick up the cube rq", "refuse"),
    ("scan45", "put the tall white can next to the red box ez", "next tall_white_can red_box"),
    ("scan55", "yo pick up the smaller white thing, the one rite up front on the right", "lift small_white_object"),
    # chef in a busy kitchen
    ("kitchen", "Soup can, in the bowl. Now.", "in soup_can bowl"),
    ("pantry", "Marker next to the Spam. Go.", "next large_marker meat_can"),
    ("mugbowl", "Mug. Up. Lift it.", "lift mug"),
    ("fruitcans", "Both cans next to the bowl! Quick!", "next soup_can bowl; next meat_can bowl"),
    ("textkitchen", "Soda can, in the bowl, quick!", "refuse"),
    ("textblocks", "Green cube on the plate! Red one too, same plate!", "on cube@left plate; on cube@right plate"),
    ("scan45", "Red can, left of the tall white can. Now!", "left red_can tall_white_can"),
    ("scan55", "Blue box to the right of the red box! Come on!", "right blue_box red_box"),
    # several steps in one message
    ("kitchen", "1. grab the banana 2. put it to the left of the mug 3. go back home", "left banana mug; home"),
    ("pantry", "First pick up the Rubik's cube, then put it back exactly where it was, then push the Spam can 5 cm toward you, and finally go home.", "at rubiks_cube; moved meat_can back 0.05; home"),
    ("mugbowl", "first push the bowl 10 cm to the right, then put the mug to the left of the bowl, then home", "moved bowl right 0.1; left mug bowl; home"),
    ("fruitcans", "ok so: first put the rubiks cube right of the meat can, then push the soup can forward 10cm, after that go home", "right rubiks_cube meat_can; moved soup_can forward 0.1; home"),
    ("textkitchen", "Steps: 1) push the cereal box 10 cm away from you 2) put the mug in front of the cereal box 3) home", "moved cereal_box forward 0.1; front mug cereal_box; home"),
    ("textblocks", "First stack the green block on the red one. Then go back to your home position.", "on cube@left cube@right; home"),
    ("scan45", "first move the red can 10 cm to the left, then put the tall white can in front of it, then go home", "moved red_can left 0.1; front tall_white_can red_can; home"),
    ("scan55", "1) grab the yellow thing 2) drop it in the white bowl 3) go home", "refuse"),
    # names objects only by where they are or what they are near
    ("kitchen", "the thing way over on the right, closest to you, push it about 10 cm away from you", "moved soup_can forward 0.1"),
    ("pantry", "the thing at the very back, push it to the right 10 cm", "moved meat_can right 0.1"),
    ("mugbowl", "the thing closer to you, put it right in front of the other one", "front mug bowl"),
    ("fruitcans", "the can way over on the left, put it between the bowl and the cube", "between soup_can bowl rubiks_cube"),
    ("textkitchen", "the can further back, put it to the right of the box", "right soda_can@back cereal_box"),
    ("textblocks", "the block that's closest to the plate, push it 5 cm away from you", "moved cube@right forward 0.05"),
    ("scan45", "the white can, put it on the box", "refuse"),
    ("scan55", "the thing right in front of the bowl at the back, slide it 10 cm toward you", "moved orange_cylinder back 0.1"),
    # hedges or asks
    ("kitchen", "could you maybe put the apple in the bowl?", "refuse"),
    ("pantry", "Would it be possible to put the foam brick next to the marker? not on top of it, just beside it", "next foam_brick large_marker"),
    ("mugbowl", "Would it be possible to put the mug on the left side of the bowl? If not, no worries.", "left mug bowl"),
    ("fruitcans", "could you maybe give the strawberry a little nudge to the left? just a bit", "moved strawberry left 0.05"),
    ("textkitchen", "Would it be possible to swap the mug and the cereal box? Only if it's easy, I mean.", "swapped mug cereal_box"),
    ("textblocks", "um could you put the red cube behind the green one? not the blue one, the green", "behind cube@right cube@left"),
    ("scan45", "would it be possible to push the red box a little bit to the right? like just a tiny bit", "moved red_box right 0.05"),
    ("scan55", "could you maybe put the big white thing on the green thing? no not the small white one, the big one", "on big_white_object green"),
]
