"""Readings found on the blind sets K2-X2 (stop 13): each was misread while its set was still blind.

Every case is an instruction written for this project by a writer who never saw the translator, with
the formula its writer gave; the translator must now give a formula equivalent to it on automata
(names included). The whole sets stay outside the repository, so that later rounds are scored
on language no rule was written for.
"""
from __future__ import annotations

import pytest

from translation_cases import check_translation

BLIND_ROUND_K2 = [
    # K2: a warehouse supervisor
    ("charging station, now. battery's almost dead",
     'F near[charging_station]'),
    ('go to the empy pallet',
     'F near[empty_pallet]'),
    ('The cold storage room. Go there and wait for the next job.',
     'F near[cold_storage_room]'),
    ('Start at the battery room, then hit the parts cage, and finish up at dock two.',
     'F (near[battery_room] & F (near[parts_cage] & F near[dock_two]))'),
    ('go to the pallet wraper, then over to the trash compactor',
     'F (near[pallet_wrapper] & F near[trash_compactor])'),
    ('Head to the outbound lane, but only once the weigh station and the label printer are both done.',
     'F near[outbound_lane] & (!near[outbound_lane] U near[weigh_station]) & (!near[outbound_lane] U '
     'near[label_printer])'),
    ("Whatever job you're on, keep clear of the acid spill next to dock two. Cleanup crew hasn't "
     'gotten to it yet.',
     'G !near[acid_spill::isnextto(dock_two)]'),
    ('Get to the charging station without going anywhere near the propane tanks.',
     'F near[charging_station] & G !near[propane_tanks]'),
    ('bring the label roll to the packing table and stay away from the conveyer while you carry it',
     'F (near[label_roll] & F (pick[label_roll] & (!near[conveyor] U (near[packing_table] & F '
     'release[label_roll, packing_table]))))'),
    ('Do the cycle count at aisle two and then aisle three, or aisle three and then aisle two, your call.',
     'F (near[aisle_two] & F near[aisle_three]) | F (near[aisle_three] & F near[aisle_two])'),
    ('Check the freezer thermometer at least twice this shift.',
     'F (near[freezer_thermometer] & F (!near[freezer_thermometer] & F near[freezer_thermometer]))'),
    ("Go by the compacter at most once, it's loud and the guys are on break.",
     '!near[compactor] W (near[compactor] & (near[compactor] W G !near[compactor]))'),
    ('Loop from the receiving dock to the shipping dock, twice in a row.',
     'F (near[receiving_dock] & F (near[shipping_dock] & F (near[receiving_dock] & F '
     'near[shipping_dock])))'),
    ('Dock four. No, five.',
     'F near[dock_five]'),
    ("Stay away from the conveyor. Actually it's shut down, so it's fine; just avoid the baler. Go to "
     'the east door.',
     'F near[east_door] & G !near[baler]'),
    ('Check the freezer door three times. No, twice is fine.',
     'F (near[freezer_door] & F (!near[freezer_door] & F near[freezer_door]))'),
    # L2: an adult child setting up a home robot for a parent
    ("Go over to Dad's bedside table, please.",
     'F near[bedside_table]'),
    ("Mum's out in the garden this afternoon, so go and keep her company by the bird bath.",
     'F near[bird_bath]'),
    ("Find Dad's walking stick.",
     'F near[walking_stick]'),
    ('please go to the front door, the carer will be here any minute',
     'F near[front_door]'),
    ("Go to the kitchen first, and after that head up to Mum's bedroom.",
     'F (near[kitchen] & F near[bedroom])'),
    ('Have a look at the front door, come back to the kitchen, and then go and check the front door '
     'one more time.',
     'F (near[front_door] & F (near[kitchen] & F near[front_door]))'),
    ("Mum likes the back door checked before anyone goes outside, so don't set foot in the garden till "
     "you've been to the back door.",
     '!near[garden] U near[back_door]'),
    ("Go to the kitchen, and please never go near the stairs, I don't want you tumbling down them.",
     'F near[kitchen] & G !near[stairs]'),
    ("Go check the front door and then the back door, but dont go near Dad's oxygen tank at any point.",
     'F (near[front_door] & F near[back_door]) & G !near[oxygen_tank]'),
    ("Take Mum's tea mug over to her armchair, and while you're carrying it, stay away from the cat.",
     'F (near[tea_mug] & F (pick[tea_mug] & (!near[cat] U (near[armchair] & F release[tea_mug, '
     'armchair]))))'),
    ("Throw out the old newspaper, and after you've got rid of it, stay out of the study.",
     'F (near[old_newspaper] & F (pick[old_newspaper] & F (near[trash_can] & F (release[old_newspaper, '
     'trash_can] & G !near[study]))))'),
    ("Head to the conservatory without going near the stairs at all, and once you're in there, avoid "
     'the plant stand as well.',
     'G !near[stairs] & F (near[conservatory] & G !near[plant_stand])'),
    ('Bring her either the blue cardigan or the grey shawl, and leave it on her armchair.',
     'F (near[blue_cardigan] & F (pick[blue_cardigan] & F (near[armchair] & F release[blue_cardigan, '
     'armchair]))) | F (near[grey_shawl] & F (pick[grey_shawl] & F (near[armchair] & F '
     'release[grey_shawl, armchair])))'),
    ('Check the front door exactly once, she gets anxious if she hears you going back and forth.',
     '!near[front_door] U (near[front_door] & (near[front_door] W G !near[front_door]))'),
    ("Check the back door three times, Dad always worries it's not locked.",
     'F (near[back_door] & F (!near[back_door] & F (near[back_door] & F (!near[back_door] & F '
     'near[back_door]))))'),
    ('While the roast is in, check on the oven exactly twice.',
     '!near[oven] U (near[oven] & (near[oven] U (!near[oven] & (!near[oven] U (near[oven] & '
     '(near[oven] W G !near[oven]))))))'),
    ('Go from the front door to the kitchen, then do that exact same trip once more.',
     'F (near[front_door] & F (near[kitchen] & F (near[front_door] & F near[kitchen])))'),
    ('Go past her bedroom door three times tonight. No, make that just twice.',
     'F (near[bedroom_door] & F (!near[bedroom_door] & F near[bedroom_door]))'),
    ("Bring Mum's glasses case to her bedside table.",
     'F (near[glasses_case] & F (pick[glasses_case] & F (near[bedside_table] & F release[glasses_case, '
     'bedside_table])))'),
    ("Put Dad's slippers on the shoe rack.",
     'F (near[slippers] & F (pick[slippers] & F (near[shoe_rack] & F release[slippers, shoe_rack])))'),
    ('Could you take the dinner plates through to the dishwasher?',
     'F (near[dinner_plates] & F (pick[dinner_plates] & F (near[dishwasher] & F release[dinner_plates, '
     'dishwasher])))'),
    ('Wait for her at the chair that sits between the fireplace and the bookcase.',
     'F near[chair::isbetween(fireplace, bookcase)]'),
    ('Her three favourite spots are the bay window, the rocking chair and the garden bench. Go to the '
     'first place I mentioned.',
     'F near[bay_window]'),
    ("Stay away from the kitchen. No, scrap that, the kitchen's fine, it's the conservatry I want you "
     'out of. Go to the lounge.',
     'F near[lounge] & G !near[conservatory]'),
    ('Fly to the chimney, and on the way back down to the lawn keep away from the TV aerial.',
     'F (near[chimney] & (!near[tv_aerial] U near[lawn]))'),
    ("Fly to the front gate, but only after you've had a look over the roof.",
     'F near[front_gate] & (!near[front_gate] U near[roof])'),
    ('Pick up the parcel on the doorstep and fly it round to the garden table.',
     'F (near[parcel::isabove(doorstep)] & F (pick[parcel::isabove(doorstep)] & F (near[garden_table] '
     '& F release[parcel::isabove(doorstep), garden_table])))'),
    # M2: a lab technician, formal
    ('Position yourself at the centrifuge next to the sink and wait there until I arrive.',
     'F near[centrifuge::isnextto(sink)]'),
    ('Hover beside the liquid nitrogen dewar and hold position.',
     'F near[liquid_nitrogen_dewar]'),
    ('Head over to the incubator, sorry, the shaking incubator, not the static one.',
     'F near[shaking_incubator]'),
    ('Visit the emergency shower prior to the fume hood.',
     'F near[fume_hood] & (!near[fume_hood] U near[emergency_shower])'),
    ('Should you need to enter the tissue culture room at any point, visit the handwash sink beforehand.',
     '!near[tissue_culture_room] W near[handwash_sink]'),
    ('Collect the cryo gloves, and refrain from approaching the sample freezer until you have them in '
     'hand; then go to the freezer.',
     'F (near[cryo_gloves] & F (pick[cryo_gloves] & F near[sample_freezer])) & (!near[sample_freezer] '
     'U pick[cryo_gloves])'),
    ('Refrain from going anywhere near the laser bench today, full stop.',
     'G !near[laser_bench]'),
    ('go to the printer, never go near the fume hod',
     'F near[printer] & G !near[fume_hood]'),
    ('Go to either the east sink or the west sink, and under no circumstances come within reach of the '
     'hazardous waste bins.',
     '(F near[east_sink] | F near[west_sink]) & G !near[hazardous_waste_bins]'),
    ('Carry the sample rack over to the cold room, and while you are transporting it, refrain from '
     'passing anywhere near the heat block, as the samples must remain cold.',
     'F (near[sample_rack] & F (pick[sample_rack] & (!near[heat_block] U (near[cold_room] & F '
     'release[sample_rack, cold_room]))))'),
    ('Make your way to the loading bay, avoiding the forklift charger until you get there; once you '
     'have arrived at the bay, kindly refrain from approaching the recycling cage for the remainder of '
     'the task, since the contractors are working on it.',
     '(!near[forklift_charger] U near[loading_bay]) & F (near[loading_bay] & G !near[recycling_cage])'),
    ('Go to the upstairs autoclave or the basement one, whichever is free.',
     'F near[upstairs_autoclave] | F near[basement_autoclave]'),
    ('Proceed to the north exit or the south exit, but on no account visit both.',
     '(F near[north_exit] & G !near[south_exit]) | (F near[south_exit] & G !near[north_exit])'),
    ('head to the autoclave or the steam sterilzer',
     'F near[autoclave] | F near[steam_sterilizer]'),
    ('You may stop by the freezer at most once; every opening lets warm air in.',
     '!near[freezer] W (near[freezer] & (near[freezer] W G !near[freezer]))'),
    ('Go to the sample freezer exactly one time and subsequently proceed to the centrifuge.',
     '(!near[sample_freezer] U (near[sample_freezer] & (near[sample_freezer] W G '
     '!near[sample_freezer]))) & F (near[sample_freezer] & F near[centrifuge])'),
    ('put the glasware in the autoclave',
     'F (near[glassware] & F (pick[glassware] & F (near[autoclave] & F release[glassware, autoclave])))'),
    ('Kindly dispose of the used gloves.',
     'F (near[used_gloves] & F (pick[used_gloves] & F (near[trash_can] & F release[used_gloves, '
     'trash_can])))'),
    ("I've left a pipette, a timer and a marker on the counter. Take the secnod item to the drawer.",
     'F (near[timer] & F (pick[timer] & F (near[drawer] & F release[timer, drawer])))'),
    ('Of the fume hood, the biosafety cabinet and the laminar flow hood, go to the first and refrain '
     'from approaching the other two.',
     'F near[fume_hood] & G !near[biosafety_cabinet] & G !near[laminar_flow_hood]'),
    ("Today's stops are the stockroom, the cold room, the autoclave and the loading bay. Do the second "
     'place I mentioned and then the fourth.',
     'F (near[cold_room] & F near[loading_bay])'),
    ('Go to the flask to the left of the hot plate. Sorry, I meant the one behind it.',
     'F near[flask::isbehind(hot_plate)]'),
    ('Take off from the launch pad, fly out to the field station, pick up the sample vial that the '
     'team has left for you there, and subsequently drop it at the rooftop pad on the biology building.',
     'F (near[field_station] & F (near[sample_vial] & F (pick[sample_vial] & F '
     '(near[rooftop_pad::isabove(biology_building)] & F release[sample_vial, '
     'rooftop_pad::isabove(biology_building)]))))'),
    # N2: a hotel housekeeping manager
    ('I need you at the linen cart on the double, thanks.',
     'F near[linen_cart]'),
    ('pls head up to room 204, guest called about the AC',
     'F near[room_204]'),
    ('Would you wait by the lobby fountain until I get there?',
     'F near[lobby_fountain]'),
    ("The concierge desk needs a body over there and you're it. Off you go.",
     'F near[concierge_desk]'),
    ('Busy morning, sorry. Could you get yourself over to the vending machnie by the gym?',
     'F near[vending_machine::isnextto(gym)]'),
    ("I need the laundry room and the supply closet both looked at, don't care which comes first.",
     'F near[laundry_room] & F near[supply_closet]'),
    ('Room 204 needs you, only after the linen cart though.',
     'F near[room_204] & (!near[room_204] U near[linen_cart])'),
    ('If you end up on the rooftop terrace at all, check with the security office first.',
     '!near[rooftop_terrace] W near[security_office]'),
    ('You can take your break in the staff room once the laundry room and the linen cart are both '
     'done, not earlier.',
     'F near[staff_room] & (!near[staff_room] U near[laundry_room]) & (!near[staff_room] U '
     'near[linen_cart])'),
    ("Go up to 204 and don't go anywhere near the luggage trolley or the fire extinguisher cabinet.",
     'F near[room_204] & G !near[luggage_trolley] & G !near[fire_extinguisher_cabinet]'),
    ("Dirty linens go in the laundry chute. Once they're in your hands, keep out of the breakfast room "
     'for the rest of the job.',
     'F (near[dirty_linens] & F (pick[dirty_linens] & G !near[breakfast_room] & F (near[laundry_chute] '
     '& F release[dirty_linens, laundry_chute])))'),
    ("Head down to the parking garage and don't go near the valet stand on the way, there's a queue of "
     "guests waiting there. Once you're actually in the garage, stay off the ramp, the maintenance "
     'crew is patching it up this afternoon.',
     '(!near[valet_stand] U near[parking_garage]) & F (near[parking_garage] & G !near[ramp])'),
    ("Go to the second floor ice machine or the third floor one, whichever's closer.",
     'F near[second_floor_ice_machine] | F near[third_floor_ice_machine]'),
    ('Bring either the spare pillow or the extra blanket up to 204.',
     'F (near[spare_pillow] & F (pick[spare_pillow] & F (near[room_204] & F release[spare_pillow, '
     'room_204]))) | F (near[extra_blanket] & F (pick[extra_blanket] & F (near[room_204] & F '
     'release[extra_blanket, room_204])))'),
    ("Take the stairs or the elevator, I don't mind.",
     'F near[stairs] | F near[elevator]'),
    ('Take the cleaning caddy and leave it either at room 204 or at the linen cart.',
     'F (near[cleaning_caddy] & F (pick[cleaning_caddy] & (F (near[room_204] & F '
     'release[cleaning_caddy, room_204]) | F (near[linen_cart] & F release[cleaning_caddy, '
     'linen_cart]))))'),
    ("go past the pool three times, lifeguard's off today",
     'F (near[pool] & F (!near[pool] & F (near[pool] & F (!near[pool] & F near[pool]))))'),
    ('Do the walk from the east stairwell to the west stairwell, then do that same walk again.',
     'F (near[east_stairwell] & F (near[west_stairwell] & F (near[east_stairwell] & F '
     'near[west_stairwell])))'),
    ('I need you in the laundry room exactly twice this shift.',
     '!near[laundry_room] U (near[laundry_room] & (near[laundry_room] U (!near[laundry_room] & '
     '(!near[laundry_room] U (near[laundry_room] & (near[laundry_room] W G !near[laundry_room]))))))'),
    ('Both the room key and the welcome card need to go to the front desk.',
     'F (near[room_key] & F (pick[room_key] & F (near[front_desk] & F release[room_key, front_desk]))) '
     '& F (near[welcome_card] & F (pick[welcome_card] & F (near[front_desk] & F release[welcome_card, '
     'front_desk])))'),
    ("We've got a lamp, a kettle and a hair dryer to return. Take the last two to the front desk.",
     'F (near[kettle] & F (pick[kettle] & F (near[front_desk] & F release[kettle, front_desk]))) & F '
     '(near[hair_dryer] & F (pick[hair_dryer] & F (near[front_desk] & F release[hair_dryer, '
     'front_desk])))'),
    ('Places to check today: the lobby, room 204 and the pool. For now just go to the second place I '
     'mentioned.',
     'F near[room_204]'),
    ('Front desk please - oh, hang on, make that the concierge desk.',
     'F near[concierge_desk]'),
    ('bring the extra pillows to room 204, sorry, 206',
     'F (near[extra_pillows] & F (pick[extra_pillows] & F (near[room_206] & F release[extra_pillows, '
     'room_206])))'),
    ('Pool, then gym. Wait, reverse that.',
     'F (near[gym] & F near[pool])'),
    ('Visit the gift shop then the front desk, and avoid the lobby bar. Actually forget the lobby bar '
     'thing.',
     'F (near[gift_shop] & F near[front_desk])'),
    ('Head to the stairwell or the elevator... scrach that, neither, just go to room 204.',
     'F near[room_204]'),
    ("Grab the parcel sitting on the ledge by the chimney and drop it at the front entrance. Don't fly "
     "near the pool while it's hanging off you.",
     'F (near[parcel::isabove(ledge::isnextto(chimney))] & F '
     '(pick[parcel::isabove(ledge::isnextto(chimney))] & (!near[pool] U (near[front_entrance] & F '
     'release[parcel::isabove(ledge::isnextto(chimney)), front_entrance]))))'),
    # O2: a drone operator and an office
    ('take the drone up and check on the duck pond',
     'F near[duck_pond]'),
    ('Land on the helipad, but before doing that, first make a pass over the weather station.',
     'F (near[weather_station] & F near[helipad])'),
    ("Check the east gate or the west gate, doesn't matter wich",
     'F near[east_gate] | F near[west_gate]'),
    ('Fly the stretch from the boathouse to the footbridge twice in a row.',
     'F (near[boathouse] & F (near[footbridge] & F (near[boathouse] & F near[footbridge])))'),
    ('Checkpoints for today: the pump house, the north field, the grain bins. Fly them last to first.',
     'F (near[grain_bins] & F (near[north_field] & F near[pump_house]))'),
    ('kitchen, mail room, reception: first go to the second place I mentiond, then to the first',
     'F (near[mail_room] & F near[kitchen])'),
    ('Survey the vineyard and then the olive grove, and stay clear of the road. Forget about the road '
     'part.',
     'F (near[vineyard] & F near[olive_grove])'),
    ('Land at the helipad or the soccer field, uh, no: the tennis courts or the soccer field.',
     'F near[tennis_courts] | F near[soccer_field]'),
    ('Fly laps over the running track, at least three of them.',
     'F (near[running_track] & F (!near[running_track] & F (near[running_track] & F '
     '(!near[running_track] & F near[running_track]))))'),
    # P2: written as the dev set is written
    ("Swing by the vending machine and the first aid kit, doesn't matter which one first.",
     'F near[vending_machine] & F near[first_aid_kit]'),
    ("Get the master key before anything else; the wine cellar is off limits until it's in your "
     'gripper. Then head down to the wine cellar.',
     'F (near[master_key] & F (pick[master_key] & F near[wine_cellar])) & (!near[wine_cellar] U '
     'pick[master_key])'),
    ('Keep away from the aquarium and the bird cage. All I need is for you to get to the bay window.',
     'F near[bay_window] & G !near[aquarium] & G !near[bird_cage]'),
    ('check the baby moniter at least twice',
     'F (near[baby_monitor] & F (!near[baby_monitor] & F near[baby_monitor]))'),
    ("There's a scarf, a hat and a pair of gloves to tidy up. Take the second thing I listed to the "
     'wardrobe.',
     'F (near[hat] & F (pick[hat] & F (near[wardrobe] & F release[hat, wardrobe])))'),
    ('Kettle, microwave, dishwasher: hit them in the reverse of that order.',
     'F (near[dishwasher] & F (near[microwave] & F near[kettle]))'),
    ("Okay so along this corridor there's a red door, a green door and a blue door. Go to the green "
     'one, and please keep well away from the other two, the guests in there are asleep.',
     'F near[green_door] & G !near[red_door] & G !near[blue_door]'),
    ("In the craft room there's an easel, a sink, a drying rack and a kiln. Go to the one that comes "
     'right after the sink.',
     'F near[drying_rack]'),
    ('Wardrobe, dresser, mirror. Visit the first and the last of those, but keep away from the one in '
     'between.',
     'F near[wardrobe] & F near[mirror] & G !near[dresser]'),
    ('Go to the lobby, then the gym, then the pool. Actually, scrap the pool and do the sauna instead.',
     'F (near[lobby] & F (near[gym] & F near[sauna]))'),
    ('Take off and hover over the forth floor terrace.',
     'F near[fourth_floor_terrace]'),
    # Q2: an office and shared kitchen, dev-like
    ('Robot, reception desk, now please.',
     'F near[reception_desk]'),
    ("ok so here's the plan for this morning: go to the filing cabinet first, then over to the window "
     "by the plants, and after that just go to the kitchen door and wait for me there until I'm back "
     'from my call',
     'F (near[filing_cabinet] & F (near[window::isnextto(plants)] & F near[kitchen_door]))'),
    ('Printer first. From the moment you get there the shredder is off limits, and then you go on to '
     'the front desk.',
     'F (near[printer] & G !near[shredder] & F near[front_desk])'),
    ("Leftovers go in the fridge. After they're in, keep away from the microwave, people are queuing "
     'there.',
     'F (near[leftovers] & F (pick[leftovers] & F (near[fridge] & F (release[leftovers, fridge] & G '
     '!near[microwave]))))'),
    ("Until you're at the mail slot the copier is off limits; after the mail slot, go to the elevator.",
     '(!near[copier] U near[mail_slot]) & F (near[mail_slot] & F near[elevator])'),
    ('Head for the dishwahser, skirting the trash can as you go. When you get there, the sink becomes '
     'off limits.',
     '(!near[trash_can] U near[dishwasher]) & F (near[dishwasher] & G !near[sink])'),
    ('Kettle or microwave, only one of the two, never both.',
     '(F near[kettle] & G !near[microwave]) | (F near[microwave] & G !near[kettle])'),
    ('The meeting room or the phone booth, go wait in one of them.',
     'F near[meeting_room] | F near[phone_booth]'),
    ("Pick up the stapler, then drop it at the front desk or on the supply shelf, wherever's closer.",
     'F (near[stapler] & F (pick[stapler] & (F (near[front_desk] & F release[stapler, front_desk]) | F '
     '(near[supply_shelf] & F release[stapler, supply_shelf]))))'),
    ('Drop the dirty plates in the sink, making only one trip to the sink.',
     'F (near[dirty_plates] & F (pick[dirty_plates] & F (near[sink] & F release[dirty_plates, sink]))) '
     '& (!near[sink] W (near[sink] & (near[sink] W G !near[sink])))'),
    ('The meeting room needs the stapler and the tape dispenser, bring them both in.',
     'F (near[stapler] & F (pick[stapler] & F (near[meeting_room] & F release[stapler, '
     'meeting_room]))) & F (near[tape_dispenser] & F (pick[tape_dispenser] & F (near[meeting_room] & F '
     'release[tape_dispenser, meeting_room])))'),
    ('Some boxes got stacked behind the reception desk, go to them.',
     'F near[boxes::isbehind(reception_desk)]'),
    ('the notebook I need is behind the monitor that sits on the desk by the door, go to it',
     'F near[notebook::isbehind(monitor::isabove(desk::isnextto(door)))]'),
    ('A fork, a knife and a spoon were left out; the first two belong in the drawer, please put them '
     'away.',
     'F (near[fork] & F (pick[fork] & F (near[drawer] & F release[fork, drawer]))) & F (near[knife] & '
     'F (pick[knife] & F (near[drawer] & F release[knife, drawer])))'),
    ('Safety round today: thermostat, fire extinguisher, fuse box. Just go to item two for now.',
     'F near[fire_extinguisher]'),
    ("can u bring my green mug to my desk... no sory, the white one, the green one's dirty",
     'F (near[white_mug] & F (pick[white_mug] & F (near[desk] & F release[white_mug, desk])))'),
    ('Go to the fridge and keep away from the microwave. Hmm, scratch that, stay away from the toaster '
     'instead.',
     'F near[fridge] & G !near[toaster]'),
    ('Whiteboard, then door. Hmm, no, door first and the whiteboard after.',
     'F (near[door] & F near[whiteboard])'),
    ('Go to the kitchen and avoid the printer on the way. Oh, actually forget the kitchen, go to the '
     'lounge instead, still avoiding the printer on the way.',
     '!near[printer] U near[lounge]'),
    ('Fly through the break room and out to the parkign lot to land, steering clear of the sprinkler '
     'heads throughout.',
     'F (near[break_room] & F near[parking_lot]) & G !near[sprinkler_heads]'),
    ('Do a pass over the supply room, then head for the lobby, and keep the front desk out of your '
     'flight path on the way to the lobby.',
     'F (near[supply_room] & (!near[front_desk] U near[lobby]))'),
    # R2: a garden, garage and hobby drone
    ('Should you need to enter the garage at any point, go by the side door beforehand.',
     '!near[garage] W near[side_door]'),
    ("The pond comes last: don't go to it until you have visited the net rack and also the fish food "
     'bin, in whatever order suits you.',
     'F near[pond] & (!near[pond] U near[net_rack]) & (!near[pond] U near[fish_food_bin])'),
    ("Go out to the lawn, but only once you've been to the fule can, and keep clear of the barbecue "
     "until you've reached the lawn.",
     'F near[lawn] & (!near[lawn] U near[fuel_can]) & (!near[barbecue] U near[lawn])'),
    ('Go to the woodpile and then the fire pit, and avoid the dog kenel the whole time, he gets excited.',
     'F (near[woodpile] & F near[fire_pit]) & G !near[dog_kennel]'),
    ('Either check the greenhouse or the cold frame, I only need one looked at.',
     'F near[greenhouse] | F near[cold_frame]'),
    ('Do the orchad first and then the vineyard, or the other way round, your choice.',
     'F (near[orchard] & F near[vineyard]) | F (near[vineyard] & F near[orchard])'),
    ("Visit the bird feeder at most once, or you'll scare the finches off.",
     '!near[bird_feeder] W (near[bird_feeder] & (near[bird_feeder] W G !near[bird_feeder]))'),
    ("There's a watering can behind the greenhouse somewhere; go and find it.",
     'F near[watering_can::isbehind(greenhouse)]'),
    ('In the garage I keep a drill press, a lathe and a bandsaw. Visit the last, then the first.',
     'F (near[bandsaw] & F near[drill_press])'),
    ("The shed, the garage, the greenhouse: go to whichever I named second, and don't go near the "
     'other two today.',
     'F near[garage] & G !near[shed] & G !near[greenhouse]'),
    ('My list for you: oil can, grease gun, tyre gauge. Go to the 3rd itme.',
     'F near[tyre_gauge]'),
    ("Keep away from the pond. Actually the pond's fine today, it's the rockery you should avoid. Go "
     'to the gate.',
     'F near[gate] & G !near[rockery]'),
    ('Go to the potting bench and then the tap, and stay away from the roses. Forget what I said about '
     'the roses.',
     'F (near[potting_bench] & F near[tap])'),
    ("Survey the hedge line, then land in the driveway, and avoid the neighbor's trampolene the whole "
     'flight.',
     'F (near[hedge_line] & F near[driveway]) & G !near[neighbors_trampoline]'),
    # S2: a hospital ward, terse
    ('need you at the nurses stn asap',
     'F near[nurses_station]'),
    ('Can you wait by the lifts for the porter?',
     'F near[lifts]'),
    ("Sluice room please, when you've got a sec.",
     'F near[sluice_room]'),
    ('go to the supply rom',
     'F near[supply_room]'),
    ('Please go and park up at your charging dock now, thanks.',
     'F near[charging_dock]'),
    ('Go via the main lifts down to pharmacy, then come back up to the ward.',
     'F (near[main_lifts] & F (near[pharmacy] & F near[ward]))'),
    ("Do a round of bay 1, bay 2 and bay 3 in that order, and finish up at the nurses' station.",
     'F (near[bay_1] & F (near[bay_2] & F (near[bay_3] & F near[nurses_station])))'),
    ("Avoid bay 5 completly, I need you at the nurses' station.",
     'F near[nurses_station] & G !near[bay_5]'),
    ("On your wya to bay 3 avoid the nurses' station, handover's going on.",
     '!near[nurses_station] U near[bay_3]'),
    ('Do bay 1 then bay 2, or the other way round, up to you.',
     'F (near[bay_1] & F near[bay_2]) | F (near[bay_2] & F near[bay_1])'),
    ('Her slippers are under bed 3, go find them.',
     'F near[slippers::isbelow(bed_3)]'),
    # T2: a school: caretaker, teachers, students
    ('Go and wait by the fire exit, the fire officer will meet you there.',
     'F near[fire_exit]'),
    ('Go to the front gate, but call in at reception on the way.',
     'F (near[reception] & F near[front_gate])'),
    ("Can you carry the register down to the office? Keep away from the playground while you've got "
     'it, the kids will grab it.',
     'F (near[register] & F (pick[register] & (!near[playground] U (near[office] & F release[register, '
     'office]))))'),
    ('Head over to the science block; from that point on the prep room is off limits. After the '
     'science block, go on to the library.',
     'F (near[science_block] & G !near[prep_room] & F near[library])'),
    ("Do the upper field then the lower field, or the other way round if that's easier.",
     'F (near[upper_field] & F near[lower_field]) | F (near[lower_field] & F near[upper_field])'),
    ('I need two trips to the photocopier, exactly two, not three.',
     '!near[photocopier] U (near[photocopier] & (near[photocopier] U (!near[photocopier] & '
     '(!near[photocopier] U (near[photocopier] & (near[photocopier] W G !near[photocopier]))))))'),
    ('Return the laptop to the IT office first, then bring its charger over there as well.',
     'F (near[laptop] & F (pick[laptop] & F (near[it_office] & F (release[laptop, it_office] & F '
     '(near[charger] & F (pick[charger] & F (near[it_office] & F release[charger, it_office])))))))'),
    ('The art room has a kiln, a sink and a drying rack. I need you at the first and last of those, '
     'but keep away from the one in the middle.',
     'F near[kiln] & F near[drying_rack] & G !near[sink]'),
    ('Go to the hall, then the gym, then the canteen. Actually, ignore the last thing, go to the staff '
     'room instead.',
     'F (near[hall] & F (near[gym] & F near[staff_room]))'),
    ('Go to either the north or south entrance... acutally just go to the north one.',
     'F near[north_entrance]'),
    # U2: a family flat and courtyard, dev-like
    ("Find the kids' scootr, it's somewhere in the flat",
     'F near[kids_scooter]'),
    ("Keep away from the courtyard gate until you've been to the bike shed and the recycling bins, "
     "doesn't matter which first.",
     '(!near[courtyard_gate] U near[bike_shed]) & (!near[courtyard_gate] U near[recycling_bins])'),
    ('Stay out of the way of the stairwell door today, ok?',
     'G !near[stairwell_door]'),
    ("Check the oven at least twice while I'm out.",
     'F (near[oven] & F (!near[oven] & F near[oven]))'),
    ("There's an apple, an orange and a banana lying around - take the last one to the fruit bowl.",
     'F (near[banana] & F (pick[banana] & F (near[fruit_bowl] & F release[banana, fruit_bowl])))'),
    # V2: a museum guard and gallery technician
    ("Where's the bronze horse statue? Go stand right next to it and wait.",
     'F near[bronze_horse_statue]'),
    ('Visit the print room, then the conservation lab, then the stairwell, and keep away from the '
     'scaffolding all night.',
     'F (near[print_room] & F (near[conservation_lab] & F near[stairwell])) & G !near[scaffolding]'),
    ("Go to the loading dock. Make sure you've been to the key cabinet before that, and only head to "
     'the parking garage once the dock is done.',
     'F near[loading_dock] & (!near[loading_dock] U near[key_cabinet]) & F near[parking_garage] & '
     '(!near[parking_garage] U near[loading_dock])'),
    ("Head into the darkroom, but before doing that, first grab the spare flashlight. Don't set foot "
     'in there without it.',
     'F (near[spare_flashlight] & F (pick[spare_flashlight] & F near[darkroom])) & (!near[darkroom] U '
     'pick[spare_flashlight])'),
    ('Go to the service elevator. Under no circumstances go near the suit of armor or the cannon.',
     'F near[service_elevator] & G !near[suit_of_armor] & G !near[cannon]'),
    ("Take the velvet rope stand back to the storage closet when you get a chance; it's been sitting "
     "in the hallway since the gala wrapped up. And please don't go near the vitrine while you're "
     'carrying it, that glass is older than both of us.',
     'F (near[velvet_rope_stand] & F (pick[velvet_rope_stand] & (!near[vitrine] U '
     '(near[storage_closet] & F release[velvet_rope_stand, storage_closet]))))'),
    ('Pass through the main hall exactly once, the floor crew just waxed it.',
     '!near[main_hall] U (near[main_hall] & (near[main_hall] W G !near[main_hall]))'),
    ('I want you to walk by the sculpture court three times before morning.',
     'F (near[sculpture_court] & F (!near[sculpture_court] & F (near[sculpture_court] & F '
     '(!near[sculpture_court] & F near[sculpture_court]))))'),
    ('Go to the atrium. You can stop by the donation box on the way if you want, but once at the very '
     'most.',
     'F near[atrium] & (!near[donation_box] W (near[donation_box] & (near[donation_box] W G '
     '!near[donation_box])))'),
    ('Throw away the candy wrapper, some kid dropped it again.',
     'F (near[candy_wrapper] & F (pick[candy_wrapper] & F (near[trash_can] & F release[candy_wrapper, '
     'trash_can])))'),
    ('Could you grab the black umbrella somebody forgot and drop it off at the lost and found?',
     'F (near[black_umbrella] & F (pick[black_umbrella] & F (near[lost_and_found] & F '
     'release[black_umbrella, lost_and_found])))'),
    ("Go to the crate right of the loading door. Er, my mistake, it's the one left of the loading door.",
     'F near[crate::isleftof(loading_door)]'),
    # W2: a restaurant manager and kitchen staff
    ('The bar comes last: do the ice machine and the glass rack first, either order, then the bar.',
     'F near[bar] & (!near[bar] U near[ice_machine]) & (!near[bar] U near[glass_rack])'),
    ('Go to the host stand, and from there out to the terrace, but stay away from the bar on that leg.',
     'F (near[host_stand] & (!near[bar] U near[terrace]))'),
    ('Run out to table 12 then come bakc to the pass, and avoid table 11 on the return trip.',
     'F (near[table_12] & (!near[table_11] U near[pass]))'),
    ('Bring the high chair over to table 12 or 14.',
     'F (near[high_chair] & F (pick[high_chair] & (F (near[table_12] & F release[high_chair, '
     'table_12]) | F (near[table_14] & F release[high_chair, table_14]))))'),
    ('the service station or the host stand, pick one and go',
     'F near[service_station] | F near[host_stand]'),
    ('take either the ketchp or the mustard over to table 12',
     'F (near[ketchup] & F (pick[ketchup] & F (near[table_12] & F release[ketchup, table_12]))) | F '
     '(near[mustard] & F (pick[mustard] & F (near[table_12] & F release[mustard, table_12])))'),
    ('hit the fryer 3 times and stay of the wet floor',
     'F (near[fryer] & F (!near[fryer] & F (near[fryer] & F (!near[fryer] & F near[fryer])))) & G '
     '!near[wet_floor]'),
    ('Can you throw away that broken glass, carefully.',
     'F (near[broken_glass] & F (pick[broken_glass] & F (near[trash_can] & F release[broken_glass, '
     'trash_can])))'),
    ('I can see a mop, a bucket and a broom lying around. Go to the third.',
     'F near[broom]'),
    ('Fly to the second floor terrace but keep clear fo the string lights.',
     'F near[second_floor_terrace] & G !near[string_lights]'),
    # X2: a farmer and a vet, yard robot and survey drone
    ("need u at the catle crush when you've a minute",
     'F near[cattle_crush]'),
    ("Do the water trough then the calf pens, and don't you go near the slurry pit while you're at it.",
     'F (near[water_trough] & F near[calf_pens]) & G !near[slurry_pit]'),
    ('head to the machinery shed and avoid the slury pit at all times',
     'F near[machinery_shed] & G !near[slurry_pit]'),
    ('Head up to the hay barn. You can call in at the dairy office if you need to, but once at most.',
     'F near[hay_barn] & (!near[dairy_office] W (near[dairy_office] & (near[dairy_office] W G '
     '!near[dairy_office])))'),
    ('Throw away that empty feed bag.',
     'F (near[empty_feed_bag] & F (pick[empty_feed_bag] & F (near[trash_can] & F '
     'release[empty_feed_bag, trash_can])))'),
    ('calf pens, feed store, milking shed - do them backwords',
     'F (near[milking_shed] & F (near[feed_store] & F near[calf_pens]))'),
    ("Go to the trailer behind the shed. No wait, it's in front of the shed, my mistake.",
     'F near[trailer::isinfrontof(shed)]'),
]


@pytest.mark.parametrize('instruction,gold', BLIND_ROUND_K2)
def test_readings_found_on_blind_sets_k2_to_x2(instruction: str, gold: str) -> None:
    check_translation(instruction, gold)
