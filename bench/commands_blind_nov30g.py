"""Blind held-out command sentences (heldout39), written 2026-11-30 08:10 UTC by a writer who read nothing of the repository."""
from __future__ import annotations

HELDOUT39: list[tuple[str, str, str]] = [
    # voice 1: a stage magician performing for an audience -- "ladies and gentlemen", the arm is "my lovely assistant", vanish = out of the way, levitate = lift, switcheroo = swap, reappear = put somewhere
    ("kitchen", "Ladies and gentlemen, observe the humble banana. With one wave of the wand my lovely assistant will make it vanish... into the red bowl! Abracadabra!", "in banana bowl"),
    ("pantry", "For my next illusion the Rubik's cube and the mustard bottle shall trade places before your very eyes. Assistant -- the switcheroo, if you please!", "swapped rubiks_cube mustard_bottle"),
    ("mugbowl", "And now... the levitating mug! Raise it up high, assistant, so the good people can see there are no strings.", "lift mug"),
    ("fruitcans", "Nothing up my sleeve. The strawberry you all saw sitting way at the back will now reappear right beside the soup can. Presto!", "next strawberry tomato_soup_can"),
    ("textkitchen", "A classic of the vanishing arts, folks: the cereal box simply disappears. Just whisk it out of the way, assistant, nobody's watching your hands.", "aside cereal_box"),
    ("textblocks", "Pick a cube, any cube. Sir, you chose green? Splendid. Assistant, the green cube goes upon the plate -- et voila!", "on cube@green plate"),
    ("scan45", "Tonight's mystery volunteer is the small white object. Watch closely as it flies through thin air and lands just in front of the red can!", "front small_white_object red_can"),
    ("scan55", "First the red box takes a little hop, ten centimetres to the right. And for the grand finale -- it returns to the exact spot it came from! Ta-da!", "moved red_box right 0.1; at red_box"),
    # voice 2: a call-centre / tech-support agent reading from a script -- "what I'm going to need you to do", "go ahead and", confirms, thanks the caller for their patience
    ("kitchen", "Okay, perfect. So what I'm going to need you to do now is take the soup can and set it down right next to the cracker box for me. Can you do that?", "next tomato_soup_can cracker_box"),
    ("pantry", "Thank you for your patience. Just to confirm, that's the black marker over on your right-hand side? Great. Go ahead and place that in front of the potted meat can, on your side of it.", "front large_marker potted_meat_can"),
    ("mugbowl", "Alright, I'm showing here that the mug is currently sitting outside the bowl. What we want to do is go ahead and put the mug inside the bowl. Let me know once that's done.", "in mug bowl"),
    ("fruitcans", "Bear with me one second... okay. Next step on my end: I'm going to have you slide the blue tin back toward yourself, about two inches. Just the two inches.", "moved potted_meat_can back 0.0508"),
    ("textkitchen", "Great, and the last item on today's ticket -- could I get you to pick up the soda can on the left and drop it into the bowl? That should resolve the issue.", "in soda_can@left bowl"),
    ("textblocks", "So I'll walk you through this. Step one, grab the blue cube. Step two, set it down to the right of the red cube. Okay? Perfect.", "right cube@blue cube@red"),
    ("scan45", "Okay, so on our side it shows the left tall white can sitting a bit too far back. Could you bring it toward you, roughly five centimetres? Thanks so much.", "moved left_tall_white_can back 0.05"),
    ("scan55", "I do apologise for the inconvenience. What I'll need from you now is to pick up the small white object and place it inside the white bowl, and then we can close this out.", "in small_white_object white_bowl"),
    # voice 3: a wedding planner doing the seating chart -- objects are guests, couples, the bride, the flower girl; "seat", "head table", "plus-one", "keep apart"
    ("kitchen", "Okay, seating chart. The mug and the bowl are a couple, they have to sit together -- bring the mug over next to the bowl.", "next mug bowl"),
    ("pantry", "The Rubik's cube is a plus-one nobody told me about. Squeeze him in between the foam brick and the potted meat, that's the only gap we've got.", "between rubiks_cube foam_brick potted_meat_can"),
    ("mugbowl", "The bowl's the head table, it doesn't move. The mug is our maid of honour and she sits right at its left-hand side.", "left mug bowl"),
    ("fruitcans", "Strawberry's the flower girl, she should be front and centre -- put her in front of the potted meat tin, closer to us.", "front strawberry potted_meat_can"),
    ("textkitchen", "Cereal box is that tall uncle who blocks everybody's photos. Seat him at the back, behind the bowl, please.", "behind cereal_box bowl"),
    ("textblocks", "The green cube is officiating today, so he stands between the happy couple -- that's the red cube and the blue cube.", "between cube@green cube@red cube@blue"),
    ("scan45", "Red box is Grandpa and he hates being up near the front. Move him behind the left tall white can, farther back from us.", "behind red_box left_tall_white_can"),
    ("scan55", "Oh no, the tall white can got seated up on top of the green box by mistake. Get him down onto the table proper, wherever there's room.", "table tall_white_can"),
    # voice 4: a train-station / airport public-address announcer -- "attention please", "would the ... please proceed to ...", "platform alteration", objects addressed as passengers
    ("kitchen", "Attention please. Would the passenger travelling as the tomato soup can please make their way to the red bowl and wait on its right-hand side. Thank you.", "right tomato_soup_can bowl"),
    ("pantry", "This is a platform alteration. The foam brick will now depart from a position ten centimetres further to the right. Ten centimetres to the right. We apologise for any inconvenience.", "moved foam_brick right 0.1"),
    ("mugbowl", "Customer announcement: the red mug is asked to proceed to the waiting area directly behind the bowl. Mug to the area behind the bowl, please.", "behind mug bowl"),
    ("fruitcans", "The Rubik's cube is requested at the bowl. Rubik's cube, please take your seat inside the bowl. Thank you for travelling with us.", "in rubiks_cube bowl"),
    ("textkitchen", "Paging the soda can on the right. The soda can on the right, please report to the front of the bowl, on the robot's side. Thank you.", "front soda_can@right bowl"),
    ("textblocks", "Service update: the red cube is now stopping three inches further forward than advertised. Three inches forward for the red cube.", "moved cube@red forward 0.0762"),
    ("scan45", "Would the small white object, currently sitting on top of the big white object, please disembark onto the table. Mind the step.", "table small_white_object"),
    ("scan55", "Attention in the yellow zone: the third yellow object from the left is requested on the left-hand side of the white bowl. Please proceed there now.", "left third_from_left_yellow_object white_bowl"),
    # voice 5: a removal-crew / furniture mover -- "on three", "coming through", "lift with your legs", "walk it along", "easy does it", blunt and matey
    ("kitchen", "Right, cracker box, on three. One, two, three -- up she goes, and set it down behind the soup can. Mind the corners.", "behind cracker_box tomato_soup_can"),
    ("pantry", "Coming through! That mustard bottle's right in the doorway, shift it out of the way for me, mate.", "aside mustard_bottle"),
    ("mugbowl", "Don't lift that bowl, just walk it along the table -- ten centimetres to your left and stop there.", "moved bowl left 0.1"),
    ("fruitcans", "Soup can and the Rubik's cube, swap 'em round. Soup goes where the cube is, cube goes where the soup is. Easy does it.", "swapped tomato_soup_can rubiks_cube"),
    ("textkitchen", "Mug's in the wrong room. Grab it by the handle, carry it across and park it on the right side of the bowl.", "right mug bowl"),
    ("textblocks", "Green cube out of the way first. Then the blue one goes down on the spot where the green one was sitting.", "aside cube@green; spot cube@blue cube@green"),
    ("scan45", "That red box -- lift with the legs, not the back, ha. Carry it round and set it down on the left side of the red can.", "left red_box red_can"),
    ("scan55", "Blue box next. Get under it, pick it up and stick it on top of the green box.", "refuse"),
    # voice 6: mixed two- and three-step tasks, and requests the robot must decline (missing objects, which-of-several ambiguity, impossible actions)
    ("kitchen", "Put the banana in the bowl, then set the mug to the left of the cracker box, and go back home when you're done.", "in banana bowl; left mug cracker_box; home"),
    ("pantry", "Put the tennis ball next to the marker.", "refuse"),
    ("mugbowl", "Pour whatever's in the mug into the bowl.", "refuse"),
    ("fruitcans", "Drop the strawberry into the bowl, and after that push the potted meat can five centimetres to the left.", "in strawberry bowl; moved potted_meat_can left 0.05"),
    ("textkitchen", "Put the red soda can in the bowl.", "refuse"),
    ("textblocks", "Pick the plate up and put it on top of the blue cube.", "refuse"),
    ("scan45", "Lift the red can and stand it on the red box.", "refuse"),
    ("scan55", "Take the tall white can off the green box and put it next to the white bowl, then nudge the red box five centimetres back toward you.", "next tall_white_can white_bowl; moved red_box back 0.05"),
]
