"""Blind held-out command sentences (heldout38), written 2026-11-30 07:19 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT38: list[tuple[str, str, str]] = [
    # voice 1: a trade-show demo presenter talking to a crowd of visitors, describing what "the arm" / "our robot" is about to do in the third person
    ("kitchen", "Alright folks, gather round. For our first demo the arm is going to pick up that banana and drop it right into the red bowl. Watch this.", "in banana bowl"),
    ("pantry", "What you'll see next, everyone, is our robot taking the black marker and laying it down on the left side of the foam brick.", "left large_marker foam_brick"),
    ("textblocks", "Now here's a crowd favourite: the arm stacks the blue cube on top of the red one. Nice and precise, you'll see.", "on cube@blue cube@red"),
    ("scan55", "Ladies and gentlemen, this table is a real scan. Our robot will simply lift the white box and hold it up so the people at the back can see it.", "lift white_box"),
    ("fruitcans", "For this one there's no grasp at all, folks - the arm just nudges the blue potted meat tin about ten centimetres forward, away from itself.", "moved potted_meat_can forward 0.1"),
    ("textkitchen", "Keep your eyes on the mug and the cereal box, because our little helper is about to make them trade places!", "swapped mug cereal_box"),
    ("scan45", "Next, the robot puts the red box in front of the red can - so between that can and the robot itself. Here it goes.", "front red_box red_can"),
    ("mugbowl", "And to close the show, the arm drops the mug into the bowl and then returns to its resting pose. Thank you all for coming!", "in mug bowl; home"),

    # voice 2: an auctioneer in full patter, calling objects "lots", "sold!", "going, going, gone", and the delivery instruction comes from "the buyer"
    ("kitchen", "Lot number four, one tin of tomato soup, sold! Deliver it over beside the cracker box, please, going, going, gone.", "next tomato_soup_can cracker_box"),
    ("pantry", "Lot seven, a blue tin of potted meat - the winning bidder wants it raised up for inspection. Up she goes, lift it high!", "lift potted_meat_can"),
    ("scan55", "Sold to the lady in the front row: the red box! Buyer wants it standing on the left-hand side of the white bowl, thank you kindly.", "left red_box white_bowl"),
    ("textkitchen", "Two soda cans on the block, but the gentleman's only bid on the one furthest to the left - that one goes into the bowl. Sold!", "in soda_can@left bowl"),
    ("fruitcans", "Lot twelve, a lovely plastic strawberry, into the bowl she goes, do I hear the bowl, going, going... sold, into the bowl!", "in strawberry bowl"),
    ("textblocks", "Who'll give me the green cube, the green cube, green cube on the plate, do I hear the plate? The plate it is, sold!", "on cube@green plate"),
    ("scan45", "Lot nine, the left tall white can, and the buyer says clear it off out of the way of the other lots. Sold, move it along.", "aside left_tall_white_can"),
    ("mugbowl", "Final lot of the day, the red mug! Buyer wants it set down to the left of the bowl. Sold, and that's the auction closed.", "left mug bowl"),

    # voice 3: a bargainer who wraps every request in a deal, offer or trade with the robot ("tell you what", "deal?", "take it or leave it")
    ("kitchen", "Tell you what - you get that mug sitting behind the cracker box and I'll stop bugging you for five whole minutes. Deal?", "behind mug cracker_box"),
    ("pantry", "Okay, bargain time. Two inches to the right for the foam brick, just a slide, and we'll call it even.", "moved foam_brick right 0.0508"),
    ("fruitcans", "I'll make it worth your while: banana ends up in the bowl, you get the rest of the afternoon off.", "in banana bowl"),
    ("textblocks", "Here's my offer. Red cube and green cube trade spots, and we're square, you and me.", "swapped cube@red cube@green"),
    ("scan55", "One favour, just one, and then I'm out of your hair: the third-from-left yellow object, take it down off the thing it's sitting on and set it on the table.", "table third_from_left_yellow_object"),
    ("scan45", "You scratch my back, I'll scratch yours - lift the small white object off the big white one and put it down next to the red box.", "next small_white_object red_box"),
    ("textkitchen", "Deal of the day: the soda can goes in the mug and I'll polish your joints tonight. Go on.", "refuse"),
    ("mugbowl", "Last offer, take it or leave it. Nudge the bowl back toward me by about ten centimetres and we're done here.", "moved bowl back 0.1"),

    # voice 4: a chess player who talks in chess moves (castle = swap, advance/retreat, squares, files, "takes the square", "home rank")
    ("kitchen", "Castle the mug and the bowl. They swap squares, like king and rook.", "swapped mug bowl"),
    ("pantry", "Rubik's cube advances one square - call a square five centimetres - straight up the board, away from me.", "moved rubiks_cube forward 0.05"),
    ("fruitcans", "The Rubik's cube takes the soup can's square: move the can off the board to one side first, then land the cube exactly where the can stood.", "aside tomato_soup_can; spot rubiks_cube tomato_soup_can"),
    ("textblocks", "Blue cube, retreat. Pull it back toward my side about four centimetres, like a bishop dropping back to defend.", "moved cube@blue back 0.04"),
    ("scan55", "Opening move: the tall white can steps down off the green box and lands on the table right beside the white bowl.", "next tall_white_can white_bowl"),
    ("textkitchen", "Knight's move for the mug - hop it over and into the bowl.", "in mug bowl"),
    ("scan45", "Shift the left tall white can one file over to the left. A file's about six centimetres, and it's a slide, not a jump.", "moved left_tall_white_can left 0.06"),
    ("mugbowl", "Deep into enemy territory: mug goes to the far side of the bowl, behind it.", "behind mug bowl"),

    # voice 5: a gardener who talks about objects as plants and the table as beds (pot up, transplant, dig up, give it room, tall ones at the back)
    ("kitchen", "Pot up the soup can in the bowl, like a seedling going into its planter.", "in tomato_soup_can bowl"),
    ("pantry", "Those two have room to spare between them - transplant the mustard bottle into the gap between the foam brick and the blue tin.", "between mustard_bottle foam_brick potted_meat_can"),
    ("fruitcans", "The strawberry's been struggling out there on its own. Move it over to sit beside the soup can, same bed, good company.", "next strawberry tomato_soup_can"),
    ("textblocks", "Red cube gets planted on the plate, please, right in the middle of that bed.", "on cube@red plate"),
    ("scan55", "Dig up the orange cylinder for me, lift the whole thing right out and hold it.", "refuse"),
    ("scan45", "No lifting that red can, it's far too big a root ball - just ease it back toward me about five centimetres so it stops shading the row.", "moved red_can back 0.05"),
    ("textkitchen", "Tall plants go at the back of the border, so the cereal box wants to stand behind the bowl.", "behind cereal_box bowl"),
    ("mugbowl", "Heel the mug in just in front of the bowl - between the bowl and me - and leave it standing there.", "front mug bowl"),

    # voice 6: mixed two- and three-step tasks, and requests the robot must decline (missing objects, which-of-several ambiguity, impossible actions)
    ("kitchen", "Put the soup can next to the banana, then the mug in the bowl, and then head back home.", "next tomato_soup_can banana; in mug bowl; home"),
    ("pantry", "Pour some of the mustard onto the foam brick.", "refuse"),
    ("fruitcans", "Swap the strawberry and the Rubik's cube, then push the bowl three centimetres to the left.", "swapped strawberry rubiks_cube; moved bowl left 0.03"),
    ("textblocks", "Put the cube on the plate.", "refuse"),
    ("textkitchen", "Grab the apple and drop it in the bowl.", "refuse"),
    ("scan45", "Pick up the red can and set it on top of the flat white box.", "refuse"),
    ("scan55", "First the small white object goes into the white bowl; after that, push the blue box back toward me 5 cm.", "in small_white_object white_bowl; moved blue_box back 0.05"),
    ("mugbowl", "Swap the mug and the bowl, and once that's done put the mug back where it originally was.", "swapped mug bowl; at mug"),
]
