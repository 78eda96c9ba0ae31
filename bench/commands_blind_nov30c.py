"""Blind held-out command sentences (heldout35), written 2026-11-30 04:17 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT35: list[tuple[str, str, str]] = [
    # voice 1: a dog trainer who talks to the arm like a well-trained dog -- "fetch", "drop it", "leave it", "heel", "good robot"
    ("kitchen", "Okay buddy, fetch the banana. Fetch! Good... now drop it in the bowl. Drop it. Good robot!", "in banana bowl"),
    ("pantry", "Leave the mustard. Leave it! Rubik's cube instead -- get it, and hold it up high for me. Hold. Hoooold.", "lift rubiks_cube"),
    ("mugbowl", "Get the mug, drop it right beside the bowl, and then heel.", "next mug bowl; home"),
    ("fruitcans", "Where's the strawberry? Find it! Find the strawberry! Yes -- bring it over and drop it in the bowl.", "in strawberry bowl"),
    ("textblocks", "Gentle... gentle. Nudge the green block towards me, two inches, no more. Good.", "moved cube@green back 0.0508"),
    ("scan55", "No, not the bowl, leave the bowl. The red box. Get it, and drop it next to the white box. Good job.", "next red_box white_box"),
    ("textkitchen", "Hey. Hey! Eyes on me. Heel. Good robot, now stay.", "home"),
    ("scan45", "Pick up the red box -- easy, don't squash it -- and set it down in front of the red can. Good!", "front red_box red_can"),
    # voice 2: a shopper who names everything by brand or shop-shelf word (Cheez-Its, Campbell's, Spam, French's, Chiquita, Kellogg's, Coke), never by the list's words
    ("kitchen", "Move the Cheez-Its so they're on the left of the Campbell's.", "left cracker_box tomato_soup_can"),
    ("pantry", "The French's should be behind the Spam tin, not where it is now.", "behind mustard_bottle potted_meat_can"),
    ("pantry", "Grab the Heinz ketchup and stand it in front of the French's.", "refuse"),
    ("fruitcans", "Spam in the bowl, please.", "in potted_meat_can bowl"),
    ("textkitchen", "Could the Kellogg's box and the Tupperware bowl trade spots?", "swapped cereal_box bowl"),
    ("textkitchen", "Left-hand Coke into the Tupperware.", "in soda_can@left bowl"),
    ("kitchen", "Slide the Campbell's over to the left, around 10 cm.", "moved tomato_soup_can left 0.10"),
    ("fruitcans", "I want the Chiquita sitting between the Spam and the bowl.", "between banana potted_meat_can bowl"),
    # voice 3: a calm yoga / meditation teacher -- slow, soothing, "gently", "let it rest", breathing cues
    ("mugbowl", "Nice and slow now. Reach for the mug, lift it gently... and let it come to rest inside the bowl. Beautiful.", "in mug bowl"),
    ("textblocks", "Let's find some stillness. Gently take the blue cube, let it float across, and allow it to settle on the plate.", "on cube@blue plate"),
    ("scan55", "Breathe in... and on the out-breath, ease the tall white can to the right, maybe five centimetres. And rest.", "moved tall_white_can right 0.05"),
    ("kitchen", "Softly, softly. Let the mug drift back towards you -- three inches or so -- and pause there.", "moved mug back 0.0762"),
    ("scan45", "That small white object is perched on the big one. Lift it away, and let it find the table. Grounded.", "table small_white_object"),
    ("pantry", "Bring the foam brick and the Rubik's cube into balance... let them gently exchange places.", "swapped foam_brick rubiks_cube"),
    ("textkitchen", "Gently does it. Let the mug come to rest on the right side of the cereal box.", "right mug cereal_box"),
    ("fruitcans", "And slowly, slowly, return to your starting pose. Soft arm. Home.", "home"),
    # voice 4: a theatre director blocking a scene -- objects are actors or props with marks, entrances, exits and "places"
    ("scan45", "Red box, you're not in this scene. Exit -- clear off somewhere out of the way.", "aside red_box"),
    ("kitchen", "Soup can, you exit first, off to the side. Then the banana takes the soup can's old mark.", "aside tomato_soup_can; spot banana tomato_soup_can"),
    ("textblocks", "Blocking change: red cube and green cube switch places. And go.", "swapped cube@red cube@green"),
    ("scan55", "The red box is lost at the back. Bring it in front of the white bowl, closer to the arm, where it reads.", "front red_box white_bowl"),
    ("mugbowl", "Let's try the mug upstage of the bowl -- behind it, farther from the arm. Hit that mark and hold.", "behind mug bowl"),
    ("pantry", "Marker, your entrance is between the foam brick and the mustard. Places, everyone!", "between large_marker foam_brick mustard_bottle"),
    ("textkitchen", "The right-hand soda can, just cheat it left a couple of inches. Two. Small adjustment.", "moved soda_can@right left 0.0508"),
    ("fruitcans", "Props! For act two the Rubik's cube lives in the bowl.", "in rubiks_cube bowl"),
    # voice 5: a pun-loving joker who wraps each request in a groan-worthy pun before getting to it
    ("kitchen", "Time for the banana to split... from the table. Get it? Just pick the banana up.", "lift banana"),
    ("mugbowl", "Let's get this bowl rolling -- push it forward four inches. No need to make a dish of it.", "moved bowl forward 0.1016"),
    ("textblocks", "The green cube's looking a bit green. Put it next to the red one so it's got some company.", "next cube@green cube@red"),
    ("scan45", "Every can is a can-didate, but I choose the left tall white can. Put it to the left of the red can.", "left left_tall_white_can red_can"),
    ("pantry", "You mustard-n't ignore this one: mustard bottle, two inches to the right. Ketchup later.", "moved mustard_bottle right 0.0508"),
    ("scan55", "Think inside the bowl for once: drop the small white object into the white bowl.", "in small_white_object white_bowl"),
    ("textkitchen", "This mug's been mugging for attention. Put it in front of the bowl, nearer the robot.", "front mug bowl"),
    ("fruitcans", "Berry important job: the strawberry goes to the left of the bowl.", "left strawberry bowl"),
    # voice 6: mixed two- and three-step tasks, and requests the robot must decline (missing objects, ambiguity, impossible actions)
    ("pantry", "Pick up the marker and lay it next to the Spam tin, then push the mustard 5 cm forward.", "next large_marker potted_meat_can; moved mustard_bottle forward 0.05"),
    ("kitchen", "Soup can in the bowl, then the banana in front of the cracker box, and after that go back home.", "in tomato_soup_can bowl; front banana cracker_box; home"),
    ("scan55", "Put the red box down left of the white bowl, and then drop the third-from-left yellow thing into that bowl.", "left red_box white_bowl; in third_from_left_yellow_object white_bowl"),
    ("mugbowl", "Pour whatever's in the mug into the bowl.", "refuse"),
    ("textblocks", "Put the cube on the plate.", "refuse"),
    ("textkitchen", "Open the cereal box and tip some cereal into the bowl.", "refuse"),
    ("scan45", "Lift the red can up and hold it there.", "refuse"),
    ("fruitcans", "Put the apple in the bowl next to the banana.", "refuse"),
]
