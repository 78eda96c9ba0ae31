"""Blind held-out command sentences (heldout37), written 2026-11-30 06:50 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT37: list[tuple[str, str, str]] = [
    # voice 1: a greeting-card rhymer who puts every request into a little rhyming couplet, loose metre, the order hidden in the verse
    ("kitchen", "Soup can, soup can, red and white, empty yourself in the bowl tonight!", "refuse"),
    ("pantry", "Roses are red, the mustard is yellow, set the black marker beside that fellow.", "next large_marker mustard_bottle"),
    ("mugbowl", "Hey diddle diddle, here's my little riddle: the mug goes in the bowl, right down the middle.", "in mug bowl"),
    ("fruitcans", "The strawberry's sitting way out at the back; bring it in front of the blue meat tin, that's the knack.", "front strawberry potted_meat_can"),
    ("textkitchen", "Cereal box, you're crowding the bowl, I fear, so three inches to your left, then stay right there.", "moved cereal_box left 0.0762"),
    ("textblocks", "One blue cube and one plate so white, pop the blue cube on the plate tonight.", "on cube@blue plate"),
    ("scan45", "The red box is hiding far off to the right; stand it left of the red can, where it's in sight.", "left red_box red_can"),
    ("scan55", "Third yellow from the left, up on your perch, up you come now, don't leave me in the lurch.", "lift third_from_left_yellow_object"),

    # voice 2: a heist / spy-film fan who first gives objects codenames ("the package", "the safehouse") and then gives the order only in codenames
    ("kitchen", "Right, crew. The mug is Falcon, the banana is Sparrow. Falcon and Sparrow trade places. Go.", "swapped mug banana"),
    ("pantry", "Target is the Rubik's cube, we call it the Box. Extraction point: the gap between the foam brick and the potted meat tin. Get the Box to extraction.", "between rubiks_cube foam_brick potted_meat_can"),
    ("mugbowl", "Our package is the mug. Secure the package, lift it and hold position.", "lift mug"),
    ("fruitcans", "Codename Jam is the strawberry, codename Vault is the bowl. Jam goes into the Vault, quiet as you like.", "in strawberry bowl"),
    ("textkitchen", "Asset one is the soda can furthest to your left, asset two is the mug. Put asset one on asset two's six, so just behind it, further away from you.", "behind soda_can@left mug"),
    ("textblocks", "The green cube is the diamond, the plate is the display case. Diamond into the case, then return to base.", "on cube@green plate; home"),
    ("scan45", "See the small white object lying on top of the big white one? That's the decoy. Lift the decoy off and keep it in the air.", "lift small_white_object"),
    ("scan55", "Lighthouse is the red box. Harbour is the white bowl. I want Lighthouse moored on the left side of Harbour.", "left red_box white_bowl"),

    # voice 3: a middle manager who talks to the arm in office buzzwords (action item, deliverable, circle back, quick win, blocker, bandwidth)
    ("kitchen", "Quick action item: the cracker box should end up to the left of the soup can, that's the key deliverable for today.", "left cracker_box tomato_soup_can"),
    ("pantry", "Let's pull the foam brick back toward you by about ten centimetres, easy quick win.", "moved foam_brick back 0.10"),
    ("mugbowl", "Per my last message, the mug and the bowl need to swap seats, can we get that actioned?", "swapped mug bowl"),
    ("fruitcans", "Low-hanging fruit first: the Rubik's cube goes on top of the potted meat tin, and then circle back to your home position.", "on rubiks_cube potted_meat_can; home"),
    ("textkitchen", "Honestly the cereal box is a blocker right now. Can you just move it out of the way?", "aside cereal_box"),
    ("textblocks", "Going forward I'd like the red cube positioned directly in front of the plate, on the side nearest you.", "front cube@red plate"),
    ("scan45", "Stakeholder ask: the left tall white can needs to live in front of the red box, closer to you.", "front left_tall_white_can red_box"),
    ("scan55", "Small ask, no pressure: if you have the bandwidth, lift the small white object for a second so I can see what's under it.", "lift small_white_object"),

    # voice 4: a hiker / orienteer who gives directions by compass, with north = straight away from the robot, east = the robot's right, west = its left
    ("kitchen", "Treat the far edge of the table as north. Slide the cracker box four inches north.", "moved cracker_box forward 0.1016"),
    ("pantry", "North is straight out from your base, so west is your left. Shift the potted meat tin three inches west.", "moved potted_meat_can left 0.0762"),
    ("mugbowl", "Map check: north is away from you. The mug belongs due south of the bowl, between the bowl and you.", "front mug bowl"),
    ("fruitcans", "If we call the far side of the table north, then the Rubik's cube should sit on the west side of the bowl.", "left rubiks_cube bowl"),
    ("textkitchen", "With north away from you and east to your right, push the more easterly of the two soda cans five centimetres north.", "moved soda_can@right forward 0.05"),
    ("textblocks", "Bearings: north is the far end of the table, west is your left hand. Place the green cube due west of the red cube.", "left cube@green cube@red"),
    ("scan45", "Okay, north means away from you. Nudge the left tall white can eight centimetres north.", "moved left_tall_white_can forward 0.08"),
    ("scan55", "North is forward from you, west is on your left. Push the orange cylinder about five centimetres west.", "moved orange_cylinder left 0.05"),

    # voice 5: someone who gives the objects feelings and friendships and asks for moves to cheer them up, comfort them or settle their quarrels
    ("kitchen", "Aw, the poor banana is all on its own over on the right. Could you bring it over next to the soup can so it has a friend?", "next banana tomato_soup_can"),
    ("pantry", "I swear the marker keeps picking on the Rubik's cube. Put the marker out of the way somewhere so it can think about what it did.", "aside large_marker"),
    ("mugbowl", "The mug's been wanting to be close to the bowl all day. Put the two of them right next to each other, would you?", "next mug bowl"),
    ("fruitcans", "The soup can is sulking in its corner. Let it sit between the blue tin and the bowl so it feels part of the group.", "between tomato_soup_can potted_meat_can bowl"),
    ("textkitchen", "The mug misses the bowl so much, they used to be inseparable. Tuck the mug inside the bowl for a cuddle.", "in mug bowl"),
    ("textblocks", "Blue cube looks lonely way over there by itself. Take it over right next to the plate, it'll feel better.", "next cube@blue plate"),
    ("scan45", "That red box looks so grumpy, it's all squashed. Give it a bit of personal space, slide it five centimetres to the right.", "moved red_box right 0.05"),
    ("scan55", "The tall white can has been standing up on the green box all day, it must be exhausted. Let it down onto the table for a rest.", "table tall_white_can"),

    # voice 6: mixed two- and three-step tasks, and requests the robot must decline (missing objects, ambiguity, impossible actions)
    ("kitchen", "Stand the cracker box to the right of the mug, then pull the soup can two inches back toward you, then go home.", "right cracker_box mug; moved tomato_soup_can back 0.0508; home"),
    ("pantry", "Grab the scissors next to the marker and put them by the mustard.", "refuse"),
    ("mugbowl", "Put the mug in the bowl and after that push the bowl 5 cm to the left.", "in mug bowl; moved bowl left 0.05"),
    ("fruitcans", "Put the apple in the bowl next to the strawberry.", "refuse"),
    ("textkitchen", "Pick up the soda can and drop it in the bowl.", "refuse"),
    ("textblocks", "Lift the plate up off the table and hold it there.", "refuse"),
    ("scan45", "Take the small white object off the big white object, set it to the left of the left tall white can, then head home.", "left small_white_object left_tall_white_can; home"),
    ("scan55", "Put the yellow object into the white bowl.", "refuse"),
]
