"""Blind held-out command sentences (heldout36), written 2026-11-30 05:40 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT36: list[tuple[str, str, str]] = [
    # voice 1: a surgeon in the operating theatre -- clipped call-outs, treats the objects like instruments on a tray, "on my mark", "thank you"
    ("kitchen", "Soup can. Up, and hold it there. Thank you.", "lift tomato_soup_can"),
    ("pantry", "Next instrument: the marker. Lay it beside the mustard bottle, nice and clean.", "next large_marker mustard_bottle"),
    ("mugbowl", "On my mark, mug into the bowl. Mark.", "in mug bowl"),
    ("fruitcans", "Strawberry to the bowl. Gently, it's delicate tissue.", "in strawberry bowl"),
    ("textkitchen", "Cereal box, retract ten centimetres toward us. Steady.", "moved cereal_box back 0.10"),
    ("textblocks", "Green cube onto the plate. Then clear the field, arm back to rest.", "on cube@green plate; home"),
    ("scan45", "The small white object. Off the big white one, down on the table. Good.", "table small_white_object"),
    ("scan55", "Tall white can, into the white bowl please. Steady hands.", "in tall_white_can white_bowl"),

    # voice 2: an anxious worrier -- fusses about knocking things over, adds warnings about what not to touch and little apologies around the one request
    ("kitchen", "Okay, um, the cracker box always looks like it's about to tip, so please be careful with it, but could it go next to the soup can? Just don't clip the banana on the way, okay?", "next cracker_box tomato_soup_can"),
    ("pantry", "Oh gosh, the Rubik's cube is right in the middle of everything. Can you slide it back toward us, about five centimetres? Slowly, please, that mustard bottle falls over if you breathe on it.", "moved rubiks_cube back 0.05"),
    ("mugbowl", "I keep worrying the mug is going to get knocked off the table. Would you put it right next to the bowl so they're together? Carefully!", "next mug bowl"),
    ("fruitcans", "Please, please don't squash the strawberry. All I need is the soup can in the bowl, that's it, nothing else.", "in tomato_soup_can bowl"),
    ("textkitchen", "Those two soda cans are so close together they make me nervous. The one on the right, could you put it in front of the mug? And don't touch the other one, it'll go over.", "front soda_can@right mug"),
    ("textblocks", "I don't like the blue cube sitting way out there, it could roll off. Would you bring it onto the plate where it's safe?", "on cube@blue plate"),
    ("scan45", "Sorry, I know it's a bit much, but the red box, could you nudge it away from you a little, like four centimetres? I keep catching my sleeve on it.", "moved red_box forward 0.04"),
    ("scan55", "That small white object is right by the edge and I'm sure it's going to fall. Could it go next to the white box instead?", "next small_white_object white_box"),

    # voice 3: a rhymer -- every request comes as a little rhyming couplet
    ("kitchen", "Banana, banana, so yellow and bright, go sit in the bowl and get out of my sight.", "in banana bowl"),
    ("pantry", "The foam brick is red and the mustard is tall; put the brick left of the bottle, and that will be all.", "left foam_brick mustard_bottle"),
    ("mugbowl", "Roses are red and so is this cup; reach for the mug and lift it straight up.", "lift mug"),
    ("fruitcans", "The Rubik's cube crowds the soup can, it's tight; so push the cube five centimetres over to the right.", "moved rubiks_cube right 0.05"),
    ("textkitchen", "Cereal and mug have been stuck in their spots; swap them around, and thanks lots and lots.", "swapped cereal_box mug"),
    ("textblocks", "Red cube, red cube, sitting alone, go beside the green one and make it your home.", "next cube@red cube@green"),
    ("scan45", "The red can is full, or so I've been told; pour it into the red box, be daring and bold.", "refuse"),
    ("scan55", "The red box stands tall at the back of the scene; set it down on the right of the white bowl so clean.", "right red_box white_bowl"),

    # voice 4: someone on the phone with another person, turning aside mid-call to give the robot a quick request
    ("kitchen", "Yeah, no, I'm listening, hang on. Robot, put the mug behind the bowl. Sorry Dave, go on.", "behind mug bowl"),
    ("pantry", "Mm-hm. Mm-hm. No, totally. Hey, the potted meat tin, stick it in front of the foam brick for me. Sorry, not you, Sarah.", "front potted_meat_can foam_brick"),
    ("mugbowl", "Hold on, Mum, I'm just getting the robot to do something. Bowl, slide it left about three inches. Yes, I'm still here.", "moved bowl left 0.0762"),
    ("fruitcans", "Can you hear me? The signal's awful. While I wait, arm, banana goes next to the strawberry. No, I wasn't talking to you.", "next banana strawberry"),
    ("textkitchen", "Yeah, she's coming at six. The left soda can, get it out of the way, would you? Sorry, that was the robot. Six, yeah.", "aside soda_can@left"),
    ("textblocks", "I'm putting you on speaker a sec. Okay robot, green cube goes between the red cube and the blue cube. Right, go ahead, I'm back.", "between cube@green cube@red cube@blue"),
    ("scan45", "Yep, I'll email it over tonight. One sec. Robot, lift the left tall white can for me. Right, where were we?", "lift left_tall_white_can"),
    ("scan55", "Sorry, sorry, the blue box is in my way here. Robot, push it back ten centimetres, toward me. Okay, carry on.", "moved blue_box back 0.10"),

    # voice 5: a sci-fi fan addressing the arm as the starship's computer -- "Computer,", "engage", "make it so", "standby position"
    ("kitchen", "Computer: relocate the tomato soup can to a position directly behind the cracker box. Engage.", "behind tomato_soup_can cracker_box"),
    ("pantry", "Computer, lock onto the mustard bottle and raise it off the deck. Make it so.", "lift mustard_bottle"),
    ("mugbowl", "Helm, bring the mug about and dock it on the left side of the bowl.", "left mug bowl"),
    ("fruitcans", "Computer, the Rubik's cube is to take the position the soup can now holds. Clear the soup can out of that sector first.", "aside tomato_soup_can; spot rubiks_cube tomato_soup_can"),
    ("textkitchen", "Course correction, computer: translate the bowl six centimetres to the right. Engage.", "moved bowl right 0.06"),
    ("textblocks", "Computer, set the red cube down on the left of the blue cube. Energize.", "left cube@red cube@blue"),
    ("scan45", "Computer, the small white object is to be placed in front of the red can. Execute.", "front small_white_object red_can"),
    ("scan55", "Computer, take the third-from-left yellow object and set it on the table, then return the arm to standby position.", "table third_from_left_yellow_object; home"),

    # voice 6: mixed two- and three-step tasks, and requests the robot must decline (missing objects, which-of-several ambiguity, impossible actions)
    ("kitchen", "Open the cracker box and tip a few crackers into the bowl.", "refuse"),
    ("pantry", "Put the marker to the left of the Rubik's cube, then push the foam brick 5 cm forward.", "left large_marker rubiks_cube; moved foam_brick forward 0.05"),
    ("mugbowl", "Take the spoon out of the mug and lay it in the bowl.", "refuse"),
    ("fruitcans", "First the strawberry into the bowl, then the banana in there as well, and after that go back home.", "in strawberry bowl; in banana bowl; home"),
    ("textkitchen", "grab the soda can", "refuse"),
    ("textblocks", "Swap the red and green cubes, and then put the blue one on the plate.", "swapped cube@red cube@green; on cube@blue plate"),
    ("scan45", "Pick up the red can and hold it up so I can read the label.", "refuse"),
    ("scan55", "Lift the orange cylinder and drop it into the white bowl.", "refuse"),
]
