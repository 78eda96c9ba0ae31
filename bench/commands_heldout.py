"""A held-out set of command sentences for ``bench_commands.py --set heldout``.

Written after the rule planner and its 153-sentence suite, without reading the planner's
grammar, in the voices of different people (polite, terse, chatty, verbless, "X goes in Y"),
over the same scenes; each sentence carries its own expected goal in the suite's goal words.
The figure *before* any planner change was recorded with these sentences as first written.
Goal keys follow the scenes as built today (sentences never change): test45's red cracker box is
``red_box`` and test55's medium white object ``big_white_object`` (same bodies, renamed by later
builds, checked against a 2792723 build); test55's grey object no longer exists alone (refuse).
"""

from __future__ import annotations

# (scene, sentence, expected goal)
HELDOUT: list[tuple[str, str, str]] = [
    # --- kitchen: cracker box, soup can, mug, bowl, banana
    ("kitchen", "could you grab the can and drop it into the bowl", "in soup_can bowl"),
    ("kitchen", "the banana goes in the bowl", "in banana bowl"),
    ("kitchen", "mug in the bowl please", "in mug bowl"),
    ("kitchen", "I'd like the soup can next to the cracker box", "next soup_can cracker_box"),
    ("kitchen", "pop the banana on the left side of the bowl", "left banana bowl"),
    ("kitchen", "hey, can you pick up that banana and hold it", "lift banana"),
    ("kitchen", "put back the can", "at soup_can"),
    ("kitchen", "get the mug and then set it down right beside the cracker box", "next mug cracker_box"),
    ("kitchen", "move the cup so it sits in front of the bowl", "front mug bowl"),
    ("kitchen", "scoot the cracker box over to the right a few centimeters", "moved cracker_box right 0.05"),
    ("kitchen", "place the tomato soup in the bowl and the banana next to the mug", "in soup_can bowl; next banana mug"),
    ("kitchen", "first lift the mug, then put it back where it was", "at mug"),
    ("kitchen", "grab the yellow thing", "lift banana"),
    ("kitchen", "put the biggest object next to the bowl", "next cracker_box bowl"),
    ("kitchen", "the cup should go behind the bowl", "behind mug bowl"),
    ("kitchen", "pick up the plate", "refuse"),
    ("kitchen", "put the thing in the bowl", "refuse"),
    ("kitchen", "take the banana, put it in the bowl, and go back home", "in banana bowl; home"),
    ("kitchen", "shove the soup can toward the robot by 5 cm", "moved soup_can back 0.05"),
    # --- pantry: mustard bottle, potted meat can, foam brick, rubik's cube, marker
    ("pantry", "grab the yellow bottle", "lift mustard_bottle"),
    ("pantry", "put the spam next to the cube", "next potted_meat_can rubiks_cube"),
    ("pantry", "could you place the brick onto the meat can", "on foam_brick potted_meat_can"),
    ("pantry", "move the marker to the right of the mustard bottle", "right marker mustard_bottle"),
    ("pantry", "the rubik's cube goes behind the mustard", "behind rubiks_cube mustard_bottle"),
    ("pantry", "pick up the shortest thing", "lift marker"),
    ("pantry", "put the foam brick and the cube next to the can", "next foam_brick potted_meat_can; next rubiks_cube potted_meat_can"),
    ("pantry", "slide the brick towards you 6 cm", "moved foam_brick back 0.06"),
    ("pantry", "put the bowl on the cube", "refuse"),
    ("pantry", "hand me the marker", "lift marker"),
    # --- mug and bowl
    ("mugbowl", "stick the mug inside the bowl", "in mug bowl"),
    ("mugbowl", "mug goes to the left of the bowl", "left mug bowl"),
    ("mugbowl", "lift the mug, then put it back", "at mug"),
    ("mugbowl", "pick up the mug and set it down to the right of the bowl, then head home", "right mug bowl; home"),
    ("mugbowl", "pick up the mug, put it down, then pick it up again", "lift mug"),
    ("mugbowl", "move the bowl away from you 5 cm", "moved bowl forward 0.05"),
    ("mugbowl", "put the bowl in front of the mug", "front bowl mug"),
    ("mugbowl", "could you please put the smaller one in the bigger one", "in mug bowl"),
    # --- fruit and cans: banana, strawberry, soup can, potted meat can, bowl, rubik's cube
    ("fruitcans", "put every fruit in the bowl", "in banana bowl; in strawberry bowl"),
    ("fruitcans", "put both cans in the bowl", "in soup_can bowl; in potted_meat_can bowl"),
    ("fruitcans", "the strawberry goes on the cube", "on strawberry rubiks_cube"),
    ("fruitcans", "take the shorter can and put it next to the bowl", "next potted_meat_can bowl"),
    ("fruitcans", "grab the can that's on the right", "lift can@right"),
    ("fruitcans", "put the rightmost can next to the banana", "next can@right banana"),
    ("fruitcans", "drop the small red fruit into the bowl", "in strawberry bowl"),
    ("fruitcans", "get the fruit", "refuse"),
    ("fruitcans", "put the cube in the bowl and then the banana too", "in rubiks_cube bowl; in banana bowl"),
    ("fruitcans", "put away the strawberry in the bowl", "in strawberry bowl"),
    # --- text scene: mug, bowl, two soda cans, cereal box
    ("textkitchen", "put the second can from the right in the bowl", "in soda_can@left bowl"),
    ("textkitchen", "move the can that's on the left next to the mug", "next soda_can@left mug"),
    ("textkitchen", "grab the soda", "refuse"),
    ("textkitchen", "pick up the left can, put it down, then grab the other one", "at soda_can@left; lift soda_can@right"),
    ("textkitchen", "put the box behind the bowl", "behind cereal_box bowl"),
    ("textkitchen", "the mug goes right between the bowl and the box", "between mug bowl cereal_box"),
    ("textkitchen", "pick up the cup and put it down next to the right soda can", "next mug soda_can@right"),
    ("textkitchen", "put both soda cans next to the cereal box", "next soda_can@left cereal_box; next soda_can@right cereal_box"),
    # --- text scene: red, blue, green cubes and a plate
    ("textblocks", "the red cube goes on the plate", "on cube@red plate"),
    ("textblocks", "put the second block from the right on the plate", "on cube@blue plate"),
    ("textblocks", "stack the green one on top of the blue one", "on cube@green cube@blue"),
    ("textblocks", "put the rightmost block on the plate", "on cube@right plate"),
    ("textblocks", "put every cube except the red one on the plate", "on cube@blue plate; on cube@green plate"),
    ("textblocks", "grab the block in the middle", "lift cube@blue"),
    ("textblocks", "move the green cube next to the plate", "next cube@green plate"),
    ("textblocks", "put the red and green blocks on the plate", "on cube@red plate; on cube@green plate"),
    ("textblocks", "put the purple cube on the plate", "refuse"),
    ("textblocks", "push the blue block away from you a bit", "moved cube@blue forward 0.05"),
    ("textblocks", "put the block on the plate", "refuse"),
    ("textblocks", "take the blue cube and put it on the plate, then put the red one on it", "on cube@blue plate; on cube@red cube@blue"),
    # --- more voices over the YCB and text scenes
    ("kitchen", "okay so I need the banana moved over next to the soup can", "next banana soup_can"),
    ("kitchen", "can the mug go in the bowl?", "in mug bowl"),
    ("mugbowl", "put it in the bowl", "refuse"),
    ("pantry", "could you push the marker forward by ten centimeters", "moved marker forward 0.10"),
    ("textblocks", "put the cubes on the plate one by one", "on cube@red plate; on cube@blue plate; on cube@green plate"),
    ("textkitchen", "I want the cereal box moved 5 cm to the left", "moved cereal_box left 0.05"),
    # --- converted scans (objects named by colour and shape from the capture)
    ("scan45", "pick up the red box", "lift red_box"),
    ("scan45", "push the white box 5 cm to the left", "moved white_box left 0.05"),
    ("scan45", "grab the red one", "refuse"),
    ("scan45", "put the red object next to the white box", "refuse"),  # two red objects now: the red can and the red cracker box
    ("scan55", "could you pick up the blue box", "lift blue_box"),
    ("scan55", "move the orange thing a little to the right", "moved orange_cylinder right 0.05"),
    ("scan55", "put the green object next to the red box", "next green red_box"),
    ("scan55", "grab the box", "refuse"),
    ("scan55", "pick up the purple thing", "refuse"),
    # 'the grey object': joined into obj13 (white_bowl since 52346e3) since 2792723 (see bench_commands.py): refuse.
    ("scan55", "push the grey one forward 4 cm", "refuse"),
    ("scan55", "the blue box goes next to the grey thing", "refuse"),
]

# A second batch, written after the planner changes that the first batch led to and measured
# before any further change: the blind figure.
HELDOUT2: list[tuple[str, str, str]] = [
    ("kitchen", "would you be so kind as to put the mug into the bowl", "in mug bowl"),
    ("kitchen", "banana to the right of the bowl", "right banana bowl"),
    ("kitchen", "lift the can up off the table please", "lift soup_can"),
    ("kitchen", "put the can down beside the banana", "next soup_can banana"),
    ("kitchen", "place the banana between the mug and the bowl", "between banana mug bowl"),
    ("kitchen", "could you nudge the bowl a tiny bit to the left", "moved bowl left 0.03"),
    ("kitchen", "pick up the cup. now put it in the bowl.", "in mug bowl"),
    ("kitchen", "move the cracker box to the left by about 6 centimetres", "moved cracker_box left 0.06"),
    ("kitchen", "grab the box of crackers", "lift cracker_box"),
    ("kitchen", "put the fruit in the bowl", "in banana bowl"),
    ("kitchen", "I'd like you to put the tomato can next to the mug", "next soup_can mug"),
    ("pantry", "put the little cube on top of the can", "on rubiks_cube potted_meat_can"),
    ("pantry", "the marker should be next to the foam brick", "next marker foam_brick"),
    ("pantry", "take the mustard and put it behind the brick", "behind mustard_bottle foam_brick"),
    ("pantry", "pick up the puzzle cube", "lift rubiks_cube"),
    ("pantry", "push the spam can back 5 cm", "moved potted_meat_can back 0.05"),
    ("pantry", "put the pen down next to the brick", "next marker foam_brick"),
    ("mugbowl", "put the cup into the dish", "in mug bowl"),
    ("mugbowl", "pick up the mug and hold it up", "lift mug"),
    ("mugbowl", "take the mug out and put it to the left of the bowl", "left mug bowl"),
    ("mugbowl", "put the larger one in front of the smaller one", "front bowl mug"),
    ("fruitcans", "put the berry in the bowl", "in strawberry bowl"),
    ("fruitcans", "throw the banana in the bowl then the strawberry", "in banana bowl; in strawberry bowl"),
    ("fruitcans", "put all the cans next to the cube", "next soup_can rubiks_cube; next potted_meat_can rubiks_cube"),
    ("fruitcans", "pick up the taller of the two cans", "lift soup_can"),
    ("fruitcans", "move the left can next to the bowl", "next can@left bowl"),
    ("fruitcans", "put the meat can on the cube", "on potted_meat_can rubiks_cube"),
    ("textkitchen", "put the cup next to the box", "next mug cereal_box"),
    ("textkitchen", "put the left soda in the bowl", "in soda_can@left bowl"),
    ("textkitchen", "grab the cereal", "lift cereal_box"),
    ("textkitchen", "pick up the can on the right, then put it down to the left of the bowl", "left soda_can@right bowl"),
    ("textkitchen", "move the box that's on the left next to the mug", "next cereal_box mug"),
    ("textblocks", "put the green block onto the red block", "on cube@green cube@red"),
    ("textblocks", "grab the red one and put it on the plate", "on cube@red plate"),
    ("textblocks", "place the cube on the far left on the plate", "on cube@left plate"),
    ("textblocks", "put the blue and red cubes next to the plate", "next cube@blue plate; next cube@red plate"),
    ("textblocks", "put the third cube from the left on the plate", "on cube@right plate"),
    ("textblocks", "stack the red block on the blue one, then go home", "on cube@red cube@blue; home"),
    ("textblocks", "put the green thing on the plate", "on cube@green plate"),
    ("textblocks", "grab the orange cube", "refuse"),
    ("scan55", "pick up the orange object", "lift orange_cylinder"),
    ("scan55", "put the red box next to the blue box", "next red_box blue_box"),
    ("scan55", "grab the white one", "refuse"),
    ("scan45", "move the white box a bit closer to you", "moved white_box back 0.05"),
    ("scan45", "put the red object in front of the white box", "refuse"),  # the red can or the red cracker box?
]

# A third batch, written after the last planner change and measured once, with no change after it.
HELDOUT3: list[tuple[str, str, str]] = [
    ("kitchen", "hey robot, toss the banana into the bowl", "in banana bowl"),
    ("kitchen", "put the mug right next to the banana please", "next mug banana"),
    ("kitchen", "could you grab the tomato soup for me and put it down on the right of the bowl", "right soup_can bowl"),
    ("kitchen", "the cracker box needs to be moved 5 cm forward", "moved cracker_box forward 0.05"),
    ("kitchen", "pick up the red can", "lift soup_can"),
    ("pantry", "please set the rubik's cube on the foam brick", "on rubiks_cube foam_brick"),
    ("pantry", "yellow bottle next to the marker", "next mustard_bottle marker"),
    ("pantry", "nudge the spam a little bit to the left", "moved potted_meat_can left 0.04"),
    ("pantry", "grab whatever is tallest", "lift mustard_bottle"),
    ("mugbowl", "take the coffee cup and put it in the bowl, thanks", "in mug bowl"),
    ("mugbowl", "move the mug to the front of the bowl", "front mug bowl"),
    ("mugbowl", "drop the mug in the bowl, then push the bowl 5 cm to the left", "in mug bowl; moved bowl left 0.05"),
    ("fruitcans", "put the red fruit in the bowl", "in strawberry bowl"),
    ("fruitcans", "put the fruits in the bowl", "in banana bowl; in strawberry bowl"),
    ("fruitcans", "place the tomato soup can on top of the rubik's cube", "on soup_can rubiks_cube"),
    ("fruitcans", "pick up the yellow can", "refuse"),
    ("textkitchen", "put the mug behind the cereal box", "behind mug cereal_box"),
    ("textkitchen", "grab the right-hand can", "lift soda_can@right"),
    ("textkitchen", "put both of the cans next to the bowl", "next soda_can@left bowl; next soda_can@right bowl"),
    ("textblocks", "put the blue cube on the plate and the green cube on the blue cube", "on cube@blue plate; on cube@green cube@blue"),
    ("textblocks", "move the plate 5 cm toward you", "moved plate back 0.05"),
    ("textblocks", "can you stack the red cube onto the green one", "on cube@red cube@green"),
    ("textblocks", "pick up the cube on the right end", "lift cube@right"),
]

# A fourth batch in other voices (careful, blunt, chatty, questions, left-dislocations, British
# verbs, "give me", a child's "can I have"), written before the typed-program session changed
# any language rule; its blind figure is in that session's report.
HELDOUT4: list[tuple[str, str, str]] = [
    ("kitchen", "carefully place the banana inside the bowl", "in banana bowl"),
    ("kitchen", "I need the mug over by the bowl", "next mug bowl"),
    ("kitchen", "chuck the soup can in the bowl", "in soup_can bowl"),
    ("kitchen", "can I have the banana?", "lift banana"),
    ("kitchen", "plonk the mug down to the left of the banana", "left mug banana"),
    ("kitchen", "please move the box a couple of centimetres to the left", "moved cracker_box left 0.02"),
    ("kitchen", "put the fruit in the bowl", "in banana bowl"),
    ("kitchen", "the bowl, push it forward 5 cm", "moved bowl forward 0.05"),
    ("kitchen", "could the banana go next to the mug?", "next banana mug"),
    ("kitchen", "grab the apple and the banana", "refuse"),
    ("pantry", "give me the rubik's cube", "lift rubiks_cube"),
    ("pantry", "place the marker in front of the foam brick", "front marker foam_brick"),
    ("pantry", "would you kindly move the mustard 5 cm to the left", "moved mustard_bottle left 0.05"),
    ("pantry", "put the cube on top of the brick", "on rubiks_cube foam_brick"),
    ("pantry", "pick up the mustard, then put it down next to the spam", "next mustard_bottle potted_meat_can"),
    ("pantry", "get the marker and put it between the cube and the brick", "between marker rubiks_cube foam_brick"),
    ("pantry", "lift the can up off the table, would you?", "lift potted_meat_can"),
    ("mugbowl", "the cup, put it in the bowl", "in mug bowl"),
    ("mugbowl", "robot, I want the mug in the bowl", "in mug bowl"),
    ("mugbowl", "push the mug 3 centimetres to the right please", "moved mug right 0.03"),
    ("mugbowl", "put the bowl to the left of the mug", "left bowl mug"),
    ("fruitcans", "stick the tomato soup in the bowl please", "in soup_can bowl"),
    ("fruitcans", "move the strawberry next to the meat can", "next strawberry potted_meat_can"),
    ("fruitcans", "pick up the smallest thing", "lift strawberry"),
    ("fruitcans", "without touching anything else, put the strawberry in the bowl", "in strawberry bowl"),
    ("fruitcans", "put the cube behind the bowl", "behind rubiks_cube bowl"),
    ("textkitchen", "move the cereal box 3 cm back toward you", "moved cereal_box back 0.03"),
    ("textkitchen", "place the bowl in front of the cereal box", "front bowl cereal_box"),
    ("textkitchen", "pick up the soda can on the left and put it in the bowl", "in soda_can@left bowl"),
    ("textblocks", "put the green cube on top of the blue one", "on cube@green cube@blue"),
    ("textblocks", "put the red cube on the plate and then go back home", "on cube@red plate; home"),
    ("textblocks", "move the blue block left 4 cm", "moved cube@blue left 0.04"),
    ("textblocks", "put the cube on the far right onto the plate", "on cube@right plate"),
    ("textblocks", "hand me the green block", "lift cube@green"),
    ("textblocks", "grab the purple cube", "refuse"),
]

# A fifth batch (2026-11-25), written blind before this session's language changes, in yet other
# voices: "ok so", "let's", "I want X to be", "needs to go", questions, terse fragments, British
# and American spellings, references by colour and by count ("both", "all the blocks").
HELDOUT5: list[tuple[str, str, str]] = [
    ("kitchen", "ok so take the banana and drop it in the bowl", "in banana bowl"),
    ("kitchen", "let's put the mug next to the cracker box", "next mug cracker_box"),
    ("kitchen", "I want the soup can to be in front of the mug", "front soup_can mug"),
    ("kitchen", "please lift the cracker box off the table", "lift cracker_box"),
    ("kitchen", "can the mug go to the right of the banana?", "right mug banana"),
    ("kitchen", "move the bowl a bit to the left", "moved bowl left 0.05"),
    ("kitchen", "put the can into the bowl and after that go home", "in soup_can bowl; home"),
    ("kitchen", "get the banana out of the way, put it behind the cracker box", "behind banana cracker_box"),
    ("kitchen", "the soup, next to the banana please", "next soup_can banana"),
    ("kitchen", "grab the orange", "refuse"),
    ("kitchen", "put the mug on the plate", "refuse"),
    ("pantry", "put the mustard bottle next to the rubik's cube", "next mustard_bottle rubiks_cube"),
    ("pantry", "could you place the brick on the meat can", "on foam_brick potted_meat_can"),
    ("pantry", "take the pen and put it to the left of the mustard", "left marker mustard_bottle"),
    ("pantry", "push the mustard back 4 cm", "moved mustard_bottle back 0.04"),
    ("pantry", "lift the red brick", "lift foam_brick"),
    ("pantry", "put the little cube in front of the mustard", "front rubiks_cube mustard_bottle"),
    ("mugbowl", "the mug needs to go inside the bowl", "in mug bowl"),
    ("mugbowl", "slide the bowl toward me 3 cm", "moved bowl back 0.03"),
    ("mugbowl", "pick up the mug, then set it down on the right side of the bowl", "right mug bowl"),
    ("fruitcans", "put both fruits in the bowl", "in banana bowl; in strawberry bowl"),
    ("fruitcans", "move the strawberry so it's next to the bowl", "next strawberry bowl"),
    ("fruitcans", "place the meat can on top of the cube", "on potted_meat_can rubiks_cube"),
    ("fruitcans", "put the soup can between the bowl and the cube", "between soup_can bowl rubiks_cube"),
    ("fruitcans", "grab the red can", "lift soup_can"),
    ("fruitcans", "put the strawberry to the left of the banana", "left strawberry banana"),
    ("fruitcans", "put the can in the bowl", "refuse"),
    ("textkitchen", "put the right soda can next to the cereal box", "next soda_can@right cereal_box"),
    ("textkitchen", "move the mug behind the cereal box", "behind mug cereal_box"),
    ("textkitchen", "put both sodas in the bowl", "in soda_can@left bowl; in soda_can@right bowl"),
    ("textkitchen", "lift the bowl", "lift bowl"),
    ("textkitchen", "put the soda can in the bowl", "refuse"),
    ("textblocks", "put the blue cube on the red cube", "on cube@blue cube@red"),
    ("textblocks", "move the plate 5 cm to the right", "moved plate right 0.05"),
    ("textblocks", "stack the green block on the plate", "on cube@green plate"),
    ("textblocks", "pick up the blue one", "lift cube@blue"),
    ("textblocks", "put all the blocks on the plate", "on cube@red plate; on cube@blue plate; on cube@green plate"),
    ("scan45", "pick up the tall white can", "lift left_tall_white_can"),
    ("scan45", "push the red can 3 cm to the right", "moved red_can right 0.03"),
    ("scan45", "put the small white object behind the red box", "behind small_white_object red_box"),
    ("scan55", "pick up the tall white can", "lift tall_white_can"),
    ("scan55", "put the white box next to the blue box", "next white_box blue_box"),
]

# A sixth batch (2026-11-25, H3), written blind before any change for it, in voices the other
# batches lack: a learner's word order, indirect and formal requests, negations that name what
# not to touch, "of the X, the one on the left", "whichever", dashes and fragments, a made-up
# object, a second object into a bowl already holding one.
HELDOUT6: list[tuple[str, str, str]] = [
    ("kitchen", "please, the banana, you put in the bowl", "in banana bowl"),
    ("kitchen", "would it be possible to move the mug so that it's beside the soup can", "next mug soup_can"),
    ("kitchen", "I'd appreciate it if you placed the soup can on the left side of the mug", "left soup_can mug"),
    ("kitchen", "I need both the mug and the soup can inside the bowl", "in mug bowl; in soup_can bowl"),
    ("kitchen", "put the pen in the bowl", "refuse"),
    ("pantry", "move the marker over so it's in front of the mustard bottle", "front marker mustard_bottle"),
    ("pantry", "don't touch the mustard, just pick up the cube", "lift rubiks_cube"),
    ("pantry", "set the brick down on the left of the spam", "left foam_brick potted_meat_can"),
    ("mugbowl", "bring the mug 5 cm closer to me", "moved mug back 0.05"),
    ("mugbowl", "swap the mug and the bowl around", "swapped mug bowl"),
    ("fruitcans", "the can that is on the left, put it next to the bowl", "next can@left bowl"),
    ("fruitcans", "put the strawberry into the bowl, and the banana next to the bowl as well", "in strawberry bowl; next banana bowl"),
    ("fruitcans", "move the soup can so it's behind the meat can", "behind soup_can potted_meat_can"),
    ("textkitchen", "of the two sodas, pick up the one on the left", "lift soda_can@left"),
    ("textkitchen", "grab whichever can is further from the mug", "lift soda_can@left"),
    ("textkitchen", "soda on the right - into the bowl with it", "in soda_can@right bowl"),
    ("textkitchen", "put the glass in the bowl", "refuse"),
    ("textblocks", "take the cube that's in the middle and put it on the plate", "on cube@blue plate"),
    ("textblocks", "lift the green cube and then set it down again", "at cube@green"),
    ("scan45", "the white box - could you nudge it 3 cm away from you", "moved white_box forward 0.03"),
    ("scan55", "I'd like the orange cylinder picked up", "lift orange_cylinder"),
]

# Written blind on 2026-11-25 before any planner change that session: other voices (texting,
# typos, fronted objects, stacked requests, questions), over the same scenes.
HELDOUT7: list[tuple[str, str, str]] = [
    ("kitchen", "yo can u drop the banana into the bowl", "in banana bowl"),
    ("kitchen", "Place the mug to the left of the bowl, please.", "left mug bowl"),
    ("kitchen", "I'd like the cracker box moved 5 centimeters to the right", "moved cracker_box right 0.05"),
    ("kitchen", "the soup can goes next to the cracker box", "next soup_can cracker_box"),
    ("kitchen", "put teh mug in the bowl", "in mug bowl"),
    ("kitchen", "pick the banana up and put it back where it was", "at banana"),
    ("kitchen", "first lift the mug, then put it down behind the soup can", "behind mug soup_can"),
    ("kitchen", "move the bowl 3 cm further away", "moved bowl forward 0.03"),
    ("kitchen", "put the knife in the bowl", "refuse"),
    ("kitchen", "could you please take the mug and put it into the bowl? thanks!", "in mug bowl"),
    ("kitchen", "Put the mug in the bowl, then move the banana 3 cm to the left", "in mug bowl; moved banana left 0.03"),
    ("kitchen", "the cracker box: lift it", "lift cracker_box"),
    ("pantry", "grab the marker pls", "lift marker"),
    ("pantry", "put the rubik's cube on the foam brick", "on rubiks_cube foam_brick"),
    ("pantry", "Would you mind placing the spam can to the right of the mustard?", "right potted_meat_can mustard_bottle"),
    ("pantry", "shift the brick 4cm left", "moved foam_brick left 0.04"),
    ("pantry", "put the mustard behind the cube", "behind mustard_bottle rubiks_cube"),
    ("pantry", "pick up the yellow bottle", "lift mustard_bottle"),
    ("pantry", "put the apple on the brick", "refuse"),
    ("pantry", "Put the marker next to the cube and the brick next to the mustard",
     "next marker rubiks_cube; next foam_brick mustard_bottle"),
    ("pantry", "put the marker down in front of the brick", "front marker foam_brick"),
    ("mugbowl", "mug in bowl", "in mug bowl"),
    ("mugbowl", "could you lift the bowl for me", "lift bowl"),
    ("mugbowl", "put the bowl to the left of the mug", "left bowl mug"),
    ("fruitcans", "put the strawberry on the rubik's cube", "on strawberry rubiks_cube"),
    ("fruitcans", "the banana should be to the right of the soup can", "right banana soup_can"),
    ("fruitcans", "pick up the small fruit", "lift strawberry"),
    ("fruitcans", "put the cube between the banana and the bowl", "between rubiks_cube banana bowl"),
    ("fruitcans", "move the meat can 5 cm towards me", "moved potted_meat_can back 0.05"),
    ("fruitcans", "i want the strawberry in the bowl and the banana too", "in strawberry bowl; in banana bowl"),
    ("fruitcans", "can you put the strawberry down on the left of the cube", "left strawberry rubiks_cube"),
    ("textkitchen", "put the left soda in the bowl", "in soda_can@left bowl"),
    ("textkitchen", "grab the cereal", "lift cereal_box"),
    ("textkitchen", "put the mug on the right of the cereal box", "right mug cereal_box"),
    ("textkitchen", "take the right-hand can and stand it next to the mug", "next soda_can@right mug"),
    ("textblocks", "red block on top of the green block", "on cube@red cube@green"),
    ("textblocks", "put the green cube between the red and the blue cubes", "between cube@green cube@red cube@blue"),
    ("textblocks", "stack the red one on the blue one", "on cube@red cube@blue"),
    ("textblocks", "put every cube on the plate", "on cube@red plate; on cube@blue plate; on cube@green plate"),
    ("textblocks", "move the plate towards me by 4 cm", "moved plate back 0.04"),
    ("textblocks", "Take the blue cube off the table", "lift cube@blue"),
    ("scan45", "lift the red can", "lift red_can"),
    ("scan45", "put the small white thing next to the white box", "next small_white_object white_box"),
    ("scan55", "pick up the green object", "lift green"),
    ("scan55", "put the white box to the left of the tall white can", "left white_box tall_white_can"),
]

from commands_blind import HELDOUT8, HELDOUT9, HELDOUT10  # noqa: E402
from commands_blind_nov26 import HELDOUT11, HELDOUT12, HELDOUT13, HELDOUT14  # noqa: E402
from commands_blind_nov26b import HELDOUT15  # noqa: E402
from commands_blind_nov26c import HELDOUT16  # noqa: E402
from commands_blind_nov27 import HELDOUT17  # noqa: E402
from commands_blind_nov29 import HELDOUT18  # noqa: E402
from commands_blind_nov29b import HELDOUT19  # noqa: E402
from commands_blind_nov29c import HELDOUT20  # noqa: E402
from commands_blind_nov29d import HELDOUT21  # noqa: E402
from commands_blind_nov29e import HELDOUT22  # noqa: E402
from commands_blind_nov29f import HELDOUT23  # noqa: E402
from commands_blind_nov29g import HELDOUT24  # noqa: E402
from commands_blind_nov29h import HELDOUT25  # noqa: E402
from commands_blind_nov29i import HELDOUT26  # noqa: E402
from commands_blind_nov29j import HELDOUT27  # noqa: E402
from commands_blind_nov29k import HELDOUT28  # noqa: E402
from commands_blind_nov29l import HELDOUT29  # noqa: E402
from commands_blind_nov29m import HELDOUT30  # noqa: E402
from commands_blind_nov29n import HELDOUT31  # noqa: E402
from commands_blind_nov29o import HELDOUT32  # noqa: E402
from commands_blind_nov30 import HELDOUT33  # noqa: E402
from commands_blind_nov30b import HELDOUT34  # noqa: E402
from commands_blind_nov30c import HELDOUT35  # noqa: E402
from commands_blind_nov30d import HELDOUT36  # noqa: E402
from commands_blind_nov30e import HELDOUT37  # noqa: E402
from commands_blind_nov30f import HELDOUT38  # noqa: E402
from commands_blind_nov30g import HELDOUT39  # noqa: E402

HELDOUT_SETS: dict[str, list[tuple[str, str, str]]] = {
    "heldout": HELDOUT, "heldout2": HELDOUT2, "heldout3": HELDOUT3, "heldout4": HELDOUT4,
    "heldout5": HELDOUT5, "heldout6": HELDOUT6, "heldout7": HELDOUT7, "heldout8": HELDOUT8, "heldout9": HELDOUT9, "heldout10": HELDOUT10,
    "heldout11": HELDOUT11, "heldout12": HELDOUT12, "heldout13": HELDOUT13, "heldout14": HELDOUT14,
    "heldout15": HELDOUT15, "heldout16": HELDOUT16, "heldout17": HELDOUT17, "heldout18": HELDOUT18, "heldout19": HELDOUT19, "heldout20": HELDOUT20, "heldout21": HELDOUT21, "heldout22": HELDOUT22, "heldout23": HELDOUT23, "heldout24": HELDOUT24, "heldout25": HELDOUT25, "heldout26": HELDOUT26, "heldout27": HELDOUT27, "heldout28": HELDOUT28,
    "heldout29": HELDOUT29, "heldout30": HELDOUT30, "heldout31": HELDOUT31, "heldout32": HELDOUT32,
    "heldout33": HELDOUT33,
    "heldout34": HELDOUT34,
    "heldout35": HELDOUT35,
    "heldout36": HELDOUT36,
    "heldout37": HELDOUT37,
    "heldout38": HELDOUT38,
    "heldout39": HELDOUT39,
}
