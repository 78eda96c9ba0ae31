"""Blind held-out command sentences written on 2026-11-26 (``--set heldout11 ... heldout14``).

Each batch was written by someone who never read the planner, its tests, the other sets or any
file of the repository (only the scenes' object lists and the goal words), added verbatim and
measured before any planner change for it. Held-out 14 was measured after all of that day's
planner changes and none was made for it.
"""

from __future__ import annotations

# Written on 2026-11-26 (12:33 UTC) by a writer who never read the planner, its tests, these sets or any file of
# the repository (only the scenes' object lists and the goal words), as six kinds of people talk; added verbatim
# and measured before any planner change for it.
HELDOUT11: list[tuple[str, str, str]] = [
    # busy parent at home, half-distracted
    ("kitchen", "can you put the banana in the bowl real quick", "in banana bowl"),
    ("fruitcans", "grab the strawberry for me and drop it in the bowl, thanks", "in strawberry bowl"),
    ("textkitchen", "um put the can in the bowl pls", "refuse"),
    ("pantry", "the marker keeps rolling, just stick it next to the rubiks cube", "next marker rubiks_cube"),
    ("mugbowl", "grab the mug. ok now put it in the bowl", "in mug bowl"),
    ("textblocks", "red block on the plate plz", "on cube@right plate"),
    ("scan45", "pick up the red can - actually no, just slide it toward you a bit", "moved red_can back 0.05"),
    ("kitchen", "slide the cracker box toward you like 10 cm and then go back home ok", "moved cracker_box back 0.10; home"),
    # elderly person unfamiliar with robots, very polite and long-winded
    ("kitchen", "Good afternoon, robot. Would you be so kind as to pick up the little red tin of tomato soup and place it inside the bowl, please? Thank you ever so much.", "in soup_can bowl"),
    ("pantry", "Hello dear, I wonder if you could lift up that yellow mustard bottle for me and just hold it up there, if it's no trouble at all.", "lift mustard_bottle"),
    ("mugbowl", "Excuse me, would you kindly pick up the mug and set it down just to the left of the bowl? My eyes aren't what they used to be, you see.", "left mug bowl"),
    ("fruitcans", "Now then, would you be so good as to gather up both of those tins and pop them into the bowl for me, please?", "in meat_can bowl; in soup_can bowl"),
    ("textblocks", "If it isn't too much bother, could you please put the green block in between the red block and the white plate? Thank you kindly.", "between cube@left cube@right plate"),
    ("scan55", "I'm so sorry to trouble you, but would you fetch me my cup of tea from the table, dear?", "refuse"),
    ("scan45", "If you would be so kind, please take the tall white can and put it down in front of the red can, a little closer to you.", "front tall_white_can red_can"),
    ("textkitchen", "Please would you place the yellow cereal box beside the white mug, and then you may go back and have a rest. Thank you, dear.", "next cereal_box mug; home"),
    # non-native English speaker
    ("kitchen", "Please you take the mug and put on right side of bowl", "right mug bowl"),
    ("pantry", "Make push the potted meat to the left side 10 centimeter", "moved meat_can left 0.10"),
    ("fruitcans", "Please put tomato can to behind of the meat can", "behind soup_can meat_can"),
    ("textkitchen", "Take the can which is more left and lift it up, please", "lift soda_can@left"),
    ("scan45", "The red box, you push it to forward 5 centimeter", "moved red_box forward 0.05"),
    ("scan55", "Put the tall white can on left side from the orange cylinder", "left tall_white_can orange_cylinder"),
    ("mugbowl", "Bring the mug more close to you, 10 centimeter", "moved mug back 0.10"),
    ("textblocks", "Take the cube and put on the plate", "refuse"),
    # teenager
    ("kitchen", "move the can all the way on the right over to the left of the bananna", "left soup_can banana"),
    ("pantry", "put the marker in front of the mustard thx", "front marker mustard_bottle"),
    ("fruitcans", "yeet the can in the bowl", "refuse"),
    ("textkitchen", "swap the mug n the cereal box rq", "swapped mug cereal_box"),
    ("scan45", "grab the lil white thing in the back n put it on the white box", "on small_white_object white_box"),
    ("scan55", "put the tall white can in the white bowl thing", "in tall_white_can white_bowl"),
    ("mugbowl", "push the bowl like 5cm to the right", "moved bowl right 0.05"),
    ("textblocks", "ok grab the green one put it on the red one then go home lol", "on cube@left cube@right; home"),
    # roboticist giving precise metric instructions
    ("kitchen", "Pick up the fork next to the bowl and place it in the mug.", "refuse"),
    ("pantry", "Pick the Rubik's cube, place it directly behind the mustard bottle, then return to the home pose.", "behind rubiks_cube mustard_bottle; home"),
    ("fruitcans", "Translate the strawberry 5 cm in -y, i.e. to the robot's right.", "moved strawberry right 0.05"),
    ("textkitchen", "Push the rightmost soda can 10 cm to the robot's right.", "moved soda_can@right right 0.10"),
    ("scan45", "Pick up the shorter white can on the right and place it to the left of the red can.", "left right_white_can red_can"),
    ("scan55", "Push the orange cylinder 0.10 m along +y, toward the robot's left.", "moved orange_cylinder left 0.10"),
    ("mugbowl", "Grasp the mug and hold it at lift height. Do not place it.", "lift mug"),
    ("textblocks", "Pick up the green cube, the one furthest from the base, and place it to the right of the plate.", "right cube@left plate"),
    # someone describing the end state they want
    ("kitchen", "I want the mug to end up in front of the banana, closer to you", "front mug banana"),
    ("pantry", "When you're done the foam brick should be sitting on top of the potted meat can", "on foam_brick meat_can"),
    ("fruitcans", "the rubik's cube should end up on the right of the meat can", "right rubiks_cube meat_can"),
    ("textkitchen", "I want the soda can that's further back to end up inside the white bowl", "in soda_can@right bowl"),
    ("scan45", "In the end the red can and the tall white can should have traded places", "swapped red_can tall_white_can"),
    ("scan55", "The yellow thing should end up next to the blue box", "refuse"),
    ("mugbowl", "Lift the mug so I can see it, but at the end it should be right back where it is now", "at mug"),
    ("textblocks", "I'd like the red cube to end up behind the plate, on the far side from you", "behind cube@right plate"),
]

# Written on 2026-11-26 (12:33 UTC) by another writer under the same rules (never saw the planner or the
# repository), six other kinds of people; added verbatim and measured before any planner change for it.
HELDOUT12: list[tuple[str, str, str]] = [
    # warehouse worker (terse imperatives, jargon)
    ("kitchen", "pick soup can, drop in bowl", "in soup_can bowl"),
    ("pantry", "Lift leftmost item. Hold.", "lift marker"),
    ("mugbowl", "mug into bowl then home it", "in mug bowl; home"),
    ("fruitcans", "pick the can. stage it by the bowl", "refuse"),
    ("textkitchen", "cereal box, relocate right of the bowl", "right cereal_box bowl"),
    ("textblocks", "red cube between blue and green. then home", "between cube@right obj2_cube cube@left; home"),
    ("scan45", "red can, shift left 10 cm", "moved red_can left 0.1"),
    ("scan55", "orange puck - push fwd 5cm", "moved orange_cylinder forward 0.05"),
    # teacher demonstrating the robot to a class
    ("kitchen", "Okay everyone, watch this. Robot, can you pick up the banana and hold it up so the class can see it?", "lift banana"),
    ("pantry", "Now class, the robot has to know its own left and right. Robot, would you put the Rubik's cube to the left of the marker, please?", "left rubiks_cube marker"),
    ("mugbowl", "This one is a little test, kids. Robot, can you put the spoon in the bowl?", "refuse"),
    ("fruitcans", "Let's see if it knows its fruit. Robot, could you put the strawberry into the bowl for us?", "in strawberry bowl"),
    ("textkitchen", "See how it has to find the mug first? Robot, place the mug next to the cereal box, and then go back to your starting position.", "next mug cereal_box; home"),
    ("textblocks", "We have three cubes here, class. Robot, which one is farthest from you? Pick that one up, please.", "lift cube@back"),
    ("scan45", "These are real scanned objects, so they look a little odd. Robot, can you push the taller of the two white cans toward you by about five centimeters?", "moved tall_white_can back 0.05"),
    ("scan55", "Now, there are lots of yellow things on this table, so watch whether it asks. Robot, please move the yellow object next to the bowl.", "refuse"),
    # someone who corrects themselves mid-sentence
    ("kitchen", "Take the soup can and put it in the... wait, no, not the bowl, put it in the, um...", "refuse"),
    ("pantry", "Push the foam brick to the left - sorry, I mean to the right - about 10 centimetres.", "moved foam_brick right 0.1"),
    ("mugbowl", "Pick up the bowl, no wait, the mug, pick up teh mug.", "lift mug"),
    ("fruitcans", "Move the soup can next to the banana, sorry, I meant next to the strawberry.", "next soup_can strawberry"),
    ("textkitchen", "Grab the red can on the right... er, no, the one closer to you, and put it in the bowl.", "in soda_can@left bowl"),
    ("textblocks", "Put the blue cube on the plate. Actually no, make that the green one.", "on cube@left plate"),
    ("scan45", "Move the red box, sorry, the red can, behind the tall white can.", "behind red_can tall_white_can"),
    ("scan55", "Push the orange thing - no, the blue box, the blue box - left about ten centimeters.", "moved blue_box left 0.1"),
    # someone dictating through speech-to-text
    ("kitchen", "push the banana too the right for centimeters than go home", "moved banana right 0.04; home"),
    ("pantry", "swap the rubix cube in the spam can", "swapped rubiks_cube meat_can"),
    ("mugbowl", "move the mug two the left of the bowl", "left mug bowl"),
    ("fruitcans", "put the rubix cube in the bowl and than go home", "in rubiks_cube bowl; home"),
    ("textkitchen", "pick up the soda can and put it in the bowl than go home", "refuse"),
    ("textblocks", "put the red cube two the left of the green cube", "left cube@right cube@left"),
    ("scan45", "pick up the white can the short one not the tall one and hold it up", "lift right_white_can"),
    ("scan55", "pick up the small white thing in the front corner on the right and hold it", "lift small_white_object"),
    # someone who identifies objects by where they are relative to other things
    ("kitchen", "Pick up whatever's sitting just behind the banana and set it down next to the can over by the box.", "next mug soup_can"),
    ("pantry", "Grab the little red thing just behind the Rubik's cube.", "lift foam_brick"),
    ("mugbowl", "Take the one that's nearer to you and put it inside the other one.", "in mug bowl"),
    ("fruitcans", "Take the can sitting in front of the strawberry and put it in the bowl.", "in meat_can bowl"),
    ("textkitchen", "Take the can that's behind the other can and put it next to the cereal box.", "next soda_can@back cereal_box"),
    ("textblocks", "Put the cube that's in between the other two onto the plate.", "on obj2_cube plate"),
    ("scan45", "Take the can that's sitting on top of the white box and put it on the table in front of the red can.", "front right_white_can red_can"),
    ("scan55", "Grab the can standing on the green thing and drop it in the white bowl at the back.", "in tall_white_can white_bowl"),
    # someone who chains three or more steps in one go
    ("kitchen", "Put the mug in the bowl, then nudge the banana forward like 10 cm, and after that go back home.", "in mug bowl; moved banana forward 0.1; home"),
    ("pantry", "Put the scissors next to the marker, then move the spam can behind the brick, then go home.", "refuse"),
    ("mugbowl", "Pick up the mug, set it down on the left side of the bowl, then put it back where it was and go home.", "at mug; home"),
    ("fruitcans", "Move the soup can in front of the spam can, put the strawberry in the bowl, then pick up the banana and hold it.", "front soup_can meat_can; in strawberry bowl; lift banana"),
    ("textkitchen", "Put both red cans in the bowl, nudge the cereal box a bit to the right, and then go back home.", "in soda_can@left bowl; in soda_can@right bowl; moved cereal_box right 0.05; home"),
    ("textblocks", "Put the red cube on the plate, then the blue one, then the green one, and then go home.", "on cube@right plate; on obj2_cube plate; on cube@left plate; home"),
    ("scan45", "Take the white can off the white box and put it to the right of the red box, then push the red can forward 5 cm, then go home.", "right right_white_can red_box; moved red_can forward 0.05; home"),
    ("scan55", "Push the red box at the back toward you 10 cm, put the small white thing on the green thing, then go home.", "moved red_box back 0.1; on small_white_object green; home"),
]

# Written on 2026-11-26 (13:20 UTC) by a writer who never read the planner, its tests, these sets or any file of
# the repository (only the scenes' object lists and the goal words), as six kinds of people talk; added verbatim
# and measured before any planner change for it (the lead's end-of-session check of the day's planner).
HELDOUT13: list[tuple[str, str, str]] = [
    # home cook talking while cooking
    ("kitchen", "ok hang on, grab the tomato soup can and drop it in the bowl for me", "in soup_can bowl"),
    ("pantry", "ugh my hands are all sticky, can you grab the mustard and just hold it up for a sec", "lift mustard_bottle"),
    ("mugbowl", "stick the mug in the bowl for now, ill wash em both later", "in mug bowl"),
    ("fruitcans", "grab the soup can, the tomato one, put it over by the banana and then go back to your normal spot", "next soup_can banana; home"),
    ("textkitchen", "im gonna pour in a sec, bring the mug over next to the bowl", "next mug bowl"),
    ("textblocks", "pass me the red one... the red cube i mean, just hold it up", "lift cube@right"),
    ("scan45", "wheres the... oh, pick up that tall white can at the back, the skinny one", "lift tall_white_can"),
    ("scan55", "quick, pass me the yellow one before this burns", "refuse"),
    # someone with British or Australian phrasing
    ("kitchen", "Pop the banana over on the left of the mug, would you? Cheers", "left banana mug"),
    ("pantry", "Right, give the Rubik's cube a wee shove to the left, ta", "moved rubiks_cube left 0.05"),
    ("mugbowl", "Pick the mug up, have a squiz at it, then pop it back where it was and go back to your starting spot", "at mug; home"),
    ("fruitcans", "Chuck the tin of tomato soup in the bowl, mate", "in soup_can bowl"),
    ("textkitchen", "The fizzy drink furthest to the left, pop that one in front of the mug, cheers", "front soda_can@left mug"),
    ("textblocks", "Stick the red cube behind the plate, there's a good lad", "behind cube@right plate"),
    ("scan45", "Give the red tin a nudge about ten centimetres towards you, ta", "moved red_can back 0.1"),
    ("scan55", "Be a love and put the teapot next to the orange thing", "refuse"),
    # someone who uses only 2-4 word commands
    ("kitchen", "mug in bowl", "in mug bowl"),
    ("pantry", "brick right of mustard", "right foam_brick mustard_bottle"),
    ("mugbowl", "mug next to bowl", "next mug bowl"),
    ("fruitcans", "all cans by bowl", "next meat_can bowl; next soup_can bowl"),
    ("textkitchen", "cereal box forward 10cm", "moved cereal_box forward 0.1"),
    ("textblocks", "grab the cube", "refuse"),
    ("scan45", "tall can forward 5cm", "moved tall_white_can forward 0.05"),
    ("scan55", "orange cylinder left 10cm", "moved orange_cylinder left 0.1"),
    # someone who asks questions instead of giving orders
    ("kitchen", "could you maybe move the mug so it sits between the banana and the cracker box?", "between mug banana cracker_box"),
    ("pantry", "is it possible to put the marker in front of the mustard bottle?", "front marker mustard_bottle"),
    ("mugbowl", "would you mind sliding the bowl a little bit to your right?", "moved bowl right 0.05"),
    ("fruitcans", "could you possibly set the strawberry on top of the rubiks cube?", "on strawberry rubiks_cube"),
    ("textkitchen", "could you hand me the soda can please?", "refuse"),
    ("textblocks", "is it possible to put the green cube in front of the red one?", "front cube@left cube@right"),
    ("scan45", "would you be able to swap the red can and the tall white can around?", "swapped red_can tall_white_can"),
    ("scan55", "can you maybe put the tall white can into the white bowl? and go home after that?", "in tall_white_can white_bowl; home"),
    # someone who names objects by their use or look
    ("kitchen", "put the red thing next to the yellow fruit", "refuse"),
    ("pantry", "the short blue tin, put it to the right of the yellow squeezy bottle", "right meat_can mustard_bottle"),
    ("mugbowl", "grab the thing with the handle you drink out of and put it in front of the round container", "front mug bowl"),
    ("fruitcans", "put the little red berry in the round dish pls", "in strawberry bowl"),
    ("textkitchen", "move the tall yellow breakfast box to the right of the round white dish", "right cereal_box bowl"),
    ("textblocks", "the green block goes on the big flat white round thing", "on cube@left plate"),
    ("scan45", "the tall skinny white cylinder, set it down next to the red box thing", "next tall_white_can red_box"),
    ("scan55", "take the tall white tin-looking thing and put it left of the flat orange disc", "left tall_white_can orange_cylinder"),
    # someone who adds constraints
    ("kitchen", "push the soup can about 10 cm forward but dont touch the cracker box", "moved soup_can forward 0.1"),
    ("pantry", "slide the foam brick behind the mustard bottle, but leave the rubik's cube exactly where it is", "behind foam_brick mustard_bottle; at rubiks_cube"),
    ("mugbowl", "very gently put the mug next to the plate, and don't bump the bowl", "refuse"),
    ("fruitcans", "push the potted meat can 10 cm to the right, slowly, and leave the strawberry where it is", "moved meat_can right 0.1; at strawberry"),
    ("textkitchen", "put the right-hand soda can behind the bowl but don't touch the other can", "behind soda_can@right bowl; at soda_can@left"),
    ("textblocks", "put the red cube on the plate without touching the green one", "on cube@right plate; at cube@left"),
    ("scan45", "carefully lift the red can up, but leave the short white can alone", "lift red_can; at right_white_can"),
    ("scan55", "move the blue box 10 cm to the left, and keep clear of the white bowl", "moved blue_box left 0.1"),
]

# Written on 2026-11-26 (13:53 UTC) by a fourth writer who never read the planner, its tests, these sets or any file
# of the repository, as six kinds of people talk; added verbatim at the end of that day's work and measured with the
# planner as it stood (no change made for it).
HELDOUT14: list[tuple[str, str, str]] = [
    # office worker tidying a desk, a bit sarcastic
    ("kitchen", "oh great, a banana on my desk, love that. just toss it in the bowl would you", "in banana bowl"),
    ("pantry", "that marker has been rolling around the edge all week. could you maybe put it next to the rubiks cube before it falls off, thanks so much", "next large_marker rubiks_cube"),
    ("mugbowl", "wow the mug is like a mile from the bowl. put it IN the bowl, clearly that's where it lives", "in mug bowl"),
    ("fruitcans", "ok robot grab the can. the can. you know which one, obviously", "refuse"),
    ("textkitchen", "put the cereal box behind the bowl so it stops blocking literally my whole view, cheers", "behind cereal_box bowl"),
    ("textblocks", "seriously who leaves cubes all over the place. put the red one on the plate and then go back home", "on cube@right plate; home"),
    ("scan45", "the red can is basically in my lap. shove it away from you a bit, if that's not too much trouble", "moved red_can forward 0.05"),
    ("scan55", "put the tall white can in the white bowl, it's basically a pencil cup anyway", "in tall_white_can white_bowl"),
    # nurse or lab technician, precise and procedural
    ("kitchen", "Step one: pick up the tomato soup can. Step two: place it behind the cracker box. Step three: return to home position.", "behind soup_can cracker_box; home"),
    ("pantry", "Procedure: retrieve the scissors from the table and hand them to me.", "refuse"),
    ("mugbowl", "First, lift the mug. Second, set it down on the left side of the bowl. Then return home.", "left mug bowl; home"),
    ("fruitcans", "Step one, transfer the strawberry into the bowl. Step two, place the rubik's cube next to the bowl.", "in strawberry bowl; next rubiks_cube bowl"),
    ("textkitchen", "Please move the white mug 5 centimetres to the right. Then stop.", "moved mug right 0.05"),
    ("textblocks", "Step 1: place the green cube on the plate. Step 2: place the blue cube on the plate. Step 3: return to home.", "on cube@left plate; on obj2_cube plate; home"),
    ("scan45", "Pick up the short white can and hold it up. Keep holding it until I say otherwise.", "lift right_white_can"),
    ("scan55", "Transfer the blue box to the left of the orange cylinder, then return to the home position.", "left blue_box orange_cylinder; home"),
    # young child
    ("kitchen", "robot pick up the nana!!", "lift banana"),
    ("pantry", "can u put the ketchup next to the rubik thing", "next mustard_bottle rubiks_cube"),
    ("mugbowl", "put the cup in the bowl pls", "in mug bowl"),
    ("fruitcans", "i want the strawbery. give it to me", "lift strawberry"),
    ("textkitchen", "put the coke in the bowl", "refuse"),
    ("textblocks", "make the red block go on the big white plate", "on cube@right plate"),
    ("scan45", "put the red can next to the big white thing at the back", "next red_can big_white_object"),
    ("scan55", "push the orange round thing a little bit to the left", "moved orange_cylinder left 0.05"),
    # someone who gives the reason with the command
    ("kitchen", "can you put the mug behind the bowl, it's in my way when I reach for the banana", "behind mug bowl"),
    ("pantry", "slide the potted meat can about 10 cm toward you, I can't reach it way back there", "moved potted_meat_can back 0.1"),
    ("mugbowl", "put the bowl right next to the mug so I can grab both at once", "next bowl mug"),
    ("fruitcans", "Put the soup can in the bowl please, I'm making lunch and need it with the rest", "in soup_can bowl"),
    ("textkitchen", "move the cereal box to the right of the bowl because it's blocking the mug", "right cereal_box bowl"),
    ("textblocks", "push the green cube 10cm to the right, it's way too close to the edge", "moved cube@left right 0.1"),
    ("scan45", "put the red can next to the red box, they go together", "next red_can red_box"),
    ("scan55", "put it in the bowl, I'll need it later", "refuse"),
    # someone who compares objects
    ("kitchen", "grab whichever is closer to you, the banana or the mug, and put it next to the cracker box", "next banana cracker_box"),
    ("pantry", "of the marker and the meat can, pick up the one that's further away from you", "lift potted_meat_can"),
    ("mugbowl", "move the smaller of the two things 10 cm forward", "moved mug forward 0.1"),
    ("fruitcans", "out of the two fruits, take the bigger one and put it to the right of the meat can", "right banana potted_meat_can"),
    ("textkitchen", "There are two soda cans. Put the one closer to you in the bowl, and the other one next to the bowl.", "in soda_can@front bowl; next soda_can@back bowl"),
    ("textblocks", "pick up the bigger cube", "refuse"),
    ("scan45", "between the two white cans, lift the taller one", "lift tall_white_can"),
    ("scan55", "out of all the yellow stuff, take the biggest one and push it 10 cm toward you", "moved first_from_left_yellow_object back 0.1"),
    # someone who gives a command and then adds to or changes part of it
    ("kitchen", "Put the banana in the bowl. Actually, make that the mug instead of the banana.", "in mug bowl"),
    ("pantry", "Move the rubik's cube 10 cm to the left. Sorry, I meant to the right.", "moved rubiks_cube right 0.1"),
    ("mugbowl", "Pick up the mug and hold it. Actually no, just put it back down where it was and go home.", "at mug; home"),
    ("fruitcans", "put the meat can in the bowl. hmm on second thought, put it to the left of the bowl instead", "left potted_meat_can bowl"),
    ("textkitchen", "Swap the mug and the cereal box. Oh, and go back home after.", "swapped mug cereal_box; home"),
    ("textblocks", "Put the blue cube on the plate. No wait, put it to the right of the plate.", "right obj2_cube plate"),
    ("scan45", "lift the short white can. actually, put it to the left of the red can while you're at it", "left right_white_can red_can"),
    ("scan55", "put the yellow thing in the white bowl. actually no, the other yellow one", "refuse"),
]
