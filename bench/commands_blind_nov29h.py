"""Blind held-out command sentences (heldout25), written 2026-11-29 17:55 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT25: list[tuple[str, str, str]] = [
    # voice 1: sports commentator telling the arm what to do next, live-broadcast style
    ("kitchen", "And the crowd is on its feet! The banana's been sitting out on the right wing all afternoon, and now the arm has to carry it across and park it on the left side of the cracker box!", "left banana cracker_box"),
    ("pantry", "Folks, you can feel the tension in this building. The Rubik's cube is right there for the taking, so arm, snatch it up and hold it high!", "lift rubiks_cube"),
    ("mugbowl", "Here we go, here we go! Bowl's sitting wide open at the far end, mug's waiting on the right, slot that mug into the bowl and this game is over!", "in mug bowl"),
    ("fruitcans", "Look at that strawberry, stranded way out at the back like a lonely striker! Arm, go fetch it and sink it in the bowl, what a finish that would be!", "in strawberry bowl"),
    ("textkitchen", "The cereal box has been a wall in midfield all match long. Coach is calling for it to shift ten centimetres over to the left, and the arm has to deliver!", "moved cereal_box left 0.1"),
    ("textblocks", "The blue cube! Everybody's watching the blue cube! This is the moment, arm, get it up onto that plate and let's hear it from the fans!", "on cube@blue plate"),
    ("scan45", "Incredible composure from the arm so far. Next play: that tall white can on the left has to go in right alongside the red can. Tight, clean, textbook!", "next left_tall_white_can red_can"),
    ("scan55", "Two minutes left on the clock, ladies and gentlemen, and the arm needs to take that tall white can off the green box and drop it straight into the white bowl!", "in tall_white_can white_bowl"),
    # voice 2: extremely indirect, negatively polite
    ("kitchen", "I'm so sorry to bother you, I really am, but I don't suppose the mug could end up somewhere to the left of the bowl? Only if it's no trouble at all.", "left mug bowl"),
    ("pantry", "Gosh, this is probably a silly thing to ask, but would it be at all possible to nudge the foam brick two inches to the left? Totally fine if not.", "moved foam_brick left 0.0508"),
    ("mugbowl", "You probably have much more important things to do, and please just ignore me if so, but I'd be ever so grateful if the bowl found its way in front of the mug.", "front bowl mug"),
    ("fruitcans", "Um, I wonder, and I feel awful asking, whether you'd mind terribly trading the places of the Rubik's cube and the soup can?", "swapped rubiks_cube tomato_soup_can"),
    ("textkitchen", "If it's not too much of an imposition, and do feel free to say no, might the mug perhaps be moved so it sits right beside the bowl?", "next mug bowl"),
    ("textblocks", "Totally your call, of course, and I don't want to be difficult, but I'd sort of love it if the green cube were sitting behind the red one?", "behind cube@green cube@red"),
    ("scan45", "I hate to impose, honestly I do, but would you be able to pick up the red can and hold it for just a sec?", "refuse"),
    ("scan55", "Sorry, sorry, last thing, I promise: would it be terribly inconvenient to push the white bowl two inches or so to the left?", "moved white_bowl left 0.0508"),
    # voice 3: carpenter / workshop shop talk
    ("kitchen", "Butt the soup can up tight against the right-hand side of the cracker box.", "right tomato_soup_can cracker_box"),
    ("pantry", "Set the foam brick dead centre between the marker and that Spam tin, nice and square.", "between foam_brick large_marker potted_meat_can"),
    ("mugbowl", "Mug's sitting a hair off. Kick it over an inch and a half to the left.", "moved mug left 0.0381"),
    ("fruitcans", "Slide the Rubik's cube three inches to the right and keep it square to the edge.", "moved rubiks_cube right 0.0762"),
    ("textkitchen", "Line the cereal box up flush behind the bowl, tight to it.", "behind cereal_box bowl"),
    ("textblocks", "Stack the red cube on the blue one, edges lined up, no overhang.", "on cube@red cube@blue"),
    ("scan45", "Pull the right white can down off that flat white box and stand it on the bench.", "table right_white_can"),
    ("scan55", "That small white piece on the right there, lay it flat on top of the orange cylinder, centred up.", "on small_white_object orange_cylinder"),
    # voice 4: over-describes every object, sometimes with one harmless wrong detail
    ("kitchen", "The Heinz tomato soup can, the red and white metal one, short, standing on the left toward the back past the cracker box, could you put that into the red plastic bowl on the right, the round empty one?", "in tomato_soup_can bowl"),
    ("pantry", "Take the yellow plastic French's mustard squeeze bottle, the tall one with the pointy cap standing about in the middle, and put it down next to the blue rectangular Spam-type tin over on the right, the one closest to me.", "next mustard_bottle potted_meat_can"),
    ("mugbowl", "Please lift the little red ceramic mug with the handle, the one sitting by itself on the right side near the front, not the big red bowl.", "lift mug"),
    ("fruitcans", "That little red plastic strawberry, the fake fruit about the size of a golf ball sitting furthest back near the middle, set it on top of the blue rectangular potted meat tin, the Spam one in the middle of the table.", "on strawberry potted_meat_can"),
    ("textkitchen", "The red soda can, the aluminium Coke-style one, the one furthest to the left of the two, way out past the mug on the far left, pop it into the red plastic bowl in the middle.", "in soda_can@left bowl"),
    ("textblocks", "The red cube, the small wooden five-centimetre one nearest me, just left of the big white plate, put it to the left of the blue cube, the blue one in the middle of the three.", "left cube@red cube@blue"),
    ("scan45", "The small white object, that flat little thing lying on top of the big white object toward the back on the right, take it off and put it on the table in front of the red can, the big reddish one near the middle.", "front small_white_object red_can"),
    ("scan55", "The big white object, the chunky white plastic piece balanced on top of the small blue object, front right near the edge, drop it into the white bowl, the deep round one at the back on the left side.", "in big_white_object white_bowl"),
    # voice 5: says what bothers them about the scene and what should change
    ("kitchen", "It bugs me that the mug is stuck out on the right and the soup can is off on the left; they'd look better the other way round. Swap them.", "swapped mug tomato_soup_can"),
    ("pantry", "That marker is practically hanging off the right side of the table and it's stressing me out. Move it ten centimetres to the left.", "moved large_marker left 0.1"),
    ("mugbowl", "The mug's so far out on the right edge I'm sure it'll get knocked off. I'd rather it were on the other side of the bowl, to its left.", "left mug bowl"),
    ("fruitcans", "I keep nearly knocking the soup can off that front corner. I'd feel better with it over to the right of the bowl, away from the edge.", "right tomato_soup_can bowl"),
    ("textkitchen", "The two soda cans are crammed so close together it makes me twitchy. Slide the right-hand one five centimetres further to the right.", "moved soda_can@right right 0.05"),
    ("textblocks", "The green cube is way out on the far left all on its own, which just looks wrong to me. Put it to the right of the plate instead.", "right cube@green plate"),
    ("scan45", "It bothers me that the left tall white can is lined up right behind the red can, it looks cluttered. Push it five centimetres further to the left.", "moved left_tall_white_can left 0.05"),
    ("scan55", "The orange cylinder is sitting exactly where I need room to work, and it's driving me mad. Get it out of the way.", "aside orange_cylinder"),
    # voice 6: mixed, multi-step tasks and requests the robot must decline
    ("kitchen", "Could you pour some of the tomato soup into the bowl for me?", "refuse"),
    ("pantry", "Grab the apple and set it next to the mustard bottle.", "refuse"),
    ("mugbowl", "Swap the mug and the bowl, and when you're done head back to your home position.", "swapped mug bowl; home"),
    ("fruitcans", "First get the banana out of the way, then put the strawberry where the banana used to be.", "aside banana; spot strawberry banana"),
    ("textkitchen", "Put the red can in the bowl.", "refuse"),
    ("textblocks", "Three things: red cube onto the plate, blue cube on top of the red one, then go home.", "on cube@red plate; on cube@blue cube@red; home"),
    ("scan45", "Open the red box and tell me what's inside.", "refuse"),
    ("scan55", "Push the yellow object forward a little.", "refuse"),
]
