"""Blind held-out command sentences (heldout26), written 2026-11-29 17:58 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT26: list[tuple[str, str, str]] = [
    # voice 1: texting, all lower case, no punctuation at all, run-on, a few abbreviations
    ("kitchen", "hey put the soup can next to the cracker box and then u can go home ty", "next tomato_soup_can cracker_box; home"),
    ("pantry", "ok so can u move the rubiks cube so its behind the mustard bottle thx", "behind rubiks_cube mustard_bottle"),
    ("mugbowl", "mug is kinda far right lol slide it left like 10 cm pls", "moved mug left 0.1"),
    ("fruitcans", "banana goes in the bowl pls n thx", "in banana bowl"),
    ("textkitchen", "omg that cereal box is in the way of everything just move it outta the way", "aside cereal_box"),
    ("textblocks", "can u stack the red cube on the blue one rn", "on cube@red cube@blue"),
    ("scan45", "the white can sitting on the flat box grab it n put it in front of the red can on the table closer to u k", "front right_white_can red_can"),
    ("scan55", "nudge the orange cylinder left like 2 inches btw", "moved orange_cylinder left 0.0508"),
    # voice 2: playful mock-archaic English
    ("kitchen", "Hearken, noble arm: set thou the mug before the cracker box, betwixt the box and thine own self.", "front mug cracker_box"),
    ("pantry", "I pray thee, raise the foam brick aloft and hold it there, that mine eyes may behold it.", "lift foam_brick"),
    ("mugbowl", "Hark, the mug and the bowl have quarrelled! Bid them exchange their places, each unto the other's seat.", "swapped mug bowl"),
    ("fruitcans", "Verily, the soup can standeth too near unto thee. Push it forth, away from thyself, some four centimetres, I beseech thee.", "moved tomato_soup_can forward 0.04"),
    ("textkitchen", "Sirrah, the soda can upon the right hand: carry it o'er and set it down on the right side of the bowl.", "right soda_can@right bowl"),
    ("textblocks", "Thou shalt place the green cube betwixt the red cube and the blue cube, an it please thee.", "between cube@green cube@red cube@blue"),
    ("scan45", "Lo, yon tall white can upon the left doth vex me sorely. Remove it from my path, good arm.", "aside left_tall_white_can"),
    ("scan55", "By my troth, lift thou the red box high above the table!", "refuse"),
    # voice 3: parent talking to a small child
    ("kitchen", "Ooh, are you strong? Let's see you lift the soup can way, way up high! Wow, look at you!", "lift tomato_soup_can"),
    ("pantry", "Who's my clever robot? Put the black marker right beside the Rubik's cube for me, okay? There you go, sweetie!", "next large_marker rubiks_cube"),
    ("mugbowl", "Let's play hide and seek! The mug wants to hide behind the bowl. Can you help it hide? Yay, clever you!", "behind mug bowl"),
    ("fruitcans", "Aww, the Rubik's cube looks lonely. Can you bring it over to sit next to the banana? Now they're friends!", "next rubiks_cube banana"),
    ("textkitchen", "Gentle hands now! Can you push the bowl a teeny bit toward me? Just 3 centimetres. Good pushing!", "moved bowl back 0.03"),
    ("textblocks", "Where's the blue cube? There it is! Can you put it on the plate, nice and careful? High five!", "on cube@blue plate"),
    ("scan45", "The big red box wants a little ride! Give it a tiny push to the right, only 3 centimetres. Wow, such a good pusher!", "moved red_box right 0.03"),
    ("scan55", "Ready for a surprise? Pick up the small white thing and pop it into the white bowl! All done, good job buddy!", "in small_white_object white_bowl"),
    # voice 4: pronouns and back-references across 2-3 short sentences
    ("kitchen", "Take the mug. Put it to the left of the cracker box. Now the soup can, but the other side.", "left mug cracker_box; right tomato_soup_can cracker_box"),
    ("pantry", "Pick up the foam brick and set it in front of the mustard bottle. Then put the marker right next to that same brick.", "front foam_brick mustard_bottle; next large_marker foam_brick"),
    ("mugbowl", "Move the mug out of the way. Okay, now bring it back. Then go home.", "aside mug; at mug; home"),
    ("fruitcans", "Drop the strawberry into the bowl. Then the Rubik's cube, same bowl.", "in strawberry bowl; in rubiks_cube bowl"),
    ("textkitchen", "Put the left soda can in the bowl. Now the other one too.", "in soda_can@left bowl; in soda_can@right bowl"),
    ("textblocks", "Red cube on the plate. Then the green one on top of it. And the last one next to the plate.", "on cube@red plate; on cube@green cube@red; next cube@blue plate"),
    ("scan45", "Take the small white object off the big white one. Put it to the left of the red can. Now put it back on top of the big one.", "left small_white_object red_can; on small_white_object big_white_object"),
    ("scan55", "Lift the tall white can off the green box. Set it next to the white bowl. Then put it back where it came from.", "next tall_white_can white_bowl; at tall_white_can"),
    # voice 5: pirate role-play (port = left, starboard = right, fore = forward, aft = back)
    ("kitchen", "Arr, shove that cracker box two inches to port, ye scallywag!", "moved cracker_box left 0.0508"),
    ("pantry", "Avast! Heave the potted meat tin two inches to starboard, lively now!", "moved potted_meat_can right 0.0508"),
    ("mugbowl", "Yo ho, matey, haul the mug round to port o' the bowl an' be quick about it!", "left mug bowl"),
    ("fruitcans", "Blimey, that Rubik's cube be driftin' astern. Drag it fore three inches, ye bilge rat!", "moved rubiks_cube forward 0.0762"),
    ("textkitchen", "Them two soda cans be mutinyin', arr! Make 'em trade places, port for starboard!", "swapped soda_can@left soda_can@right"),
    ("textblocks", "Ahoy! Shove the blue cube two inches aft, toward ol' Cap'n here.", "moved cube@blue back 0.0508"),
    ("scan45", "Shiver me timbers, that red can be blockin' me view. Push it fore by four centimetres, arr!", "moved red_can forward 0.04"),
    ("scan55", "Weigh anchor on that orange cylinder, matey, and land it to port o' the white bowl, yarr!", "left orange_cylinder white_bowl"),
    # voice 6: mixed multi-step tasks and requests the robot must decline
    ("kitchen", "Pour the soup from the can into the bowl, please.", "refuse"),
    ("pantry", "Swap the foam brick and the Rubik's cube, then put the marker in front of the potted meat can, and after that head home.", "swapped foam_brick rubiks_cube; front large_marker potted_meat_can; home"),
    ("mugbowl", "Could you put the mug on the plate?", "refuse"),
    ("fruitcans", "Pick up the strawberry and put it on top of the potted meat can, then push the Rubik's cube 4 cm to the right.", "on strawberry potted_meat_can; moved rubiks_cube right 0.04"),
    ("textkitchen", "Grab the red soda can and drop it in the bowl.", "refuse"),
    ("textblocks", "Put the yellow cube on the plate.", "refuse"),
    ("scan45", "Open the red box and take out whatever is inside.", "refuse"),
    ("scan55", "Move the small white object out of the way, then push the blue box 3 cm forward, then return home.", "aside small_white_object; moved blue_box forward 0.03; home"),
]
