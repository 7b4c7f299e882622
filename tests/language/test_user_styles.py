"""Issue 28: how people write. Connectives ("in that order", "before you X, Y"), references across
sentences, landmarks and sources, descriptive names, plurals, filler verbs; check 1 (the word accounting)
must accept what the reading uses and still name what it does not."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from nl2hltl2plan.language.accounting import account
from nl2hltl2plan.language.grammar import parse_instruction
from nl2hltl2plan.language.task_specs import BaseTaskSpec, transitive_closure

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))

ROOM = {
    "Apple", "Bread", "Egg", "Mug", "Cup", "Plate", "Pan", "Fork", "Spatula", "Kettle", "SoapBar",
    "Plunger", "Candle", "KeyChain", "Watch", "Fridge", "Microwave", "CounterTop", "SinkBasin", "Faucet",
    "Cabinet", "Drawer", "Toilet", "Dresser", "Safe", "Box", "GarbageCan", "CoffeeMachine", "Desk",
    "Pencil", "Pen", "DeskLamp",
}  # fmt: skip


def read(text: str) -> tuple[list[str], set[tuple[str, str]], list[str]]:
    r = parse_instruction(text, ROOM, "room", affordances=lambda t: None)
    name = {t.id: t.summary() for t in r.tasks}
    order = {(name[a], name[b]) for a, b in transitive_closure(r.before, list(name))}
    return [t.summary() for t in r.tasks], order, r.unparsed


PUT_EGG, PUT_MUG = "place Egg -> Fridge", "place Mug -> SinkBasin"


@pytest.mark.parametrize(
    "text, tasks, order",
    [
        (
            "put the mug in the sink and the egg in the fridge, in that order",
            [PUT_MUG, PUT_EGG],
            {(PUT_MUG, PUT_EGG)},
        ),
        ("put the mug in the sink and the egg in the fridge in any order", [PUT_MUG, PUT_EGG], set()),
        (
            "before you put the egg in the fridge, put the mug in the sink",
            [PUT_MUG, PUT_EGG],
            {(PUT_MUG, PUT_EGG)},
        ),
        (
            "prior to putting the egg in the fridge, put the mug in the sink",
            [PUT_MUG, PUT_EGG],
            {(PUT_MUG, PUT_EGG)},
        ),
        ("Put the egg in the fridge. Concurrently, put the mug in the sink.", [PUT_EGG, PUT_MUG], set()),
        (
            "put the egg in the fridge first and then put the mug in the sink",
            [PUT_EGG, PUT_MUG],
            {(PUT_EGG, PUT_MUG)},
        ),
        (
            "put the egg in the fridge and when you're done put the mug in the sink",
            [PUT_EGG, PUT_MUG],
            {(PUT_EGG, PUT_MUG)},
        ),
        (
            "put the egg in the fridge, and once that's done put the mug in the sink",
            [PUT_EGG, PUT_MUG],
            {(PUT_EGG, PUT_MUG)},
        ),
        *[  # a done-clause opening a sentence with no comma: "both" / "they" are the tasks before, no count
            (
                f"put the egg in the fridge. then put the mug in the sink. {opener} put the pen in a drawer",
                [PUT_EGG, PUT_MUG, "place Pen -> Drawer"],
                {(PUT_EGG, PUT_MUG), (PUT_EGG, "place Pen -> Drawer"), (PUT_MUG, "place Pen -> Drawer")},
            )
            for opener in ("once both are done", "Once both are finished", "When both are done")
        ],
        (  # "it" in a new sentence after a finished task: a task of its own on the same object
            "put the mug in the sink. then put it in the coffee machine",
            [PUT_MUG, "place Mug -> CoffeeMachine"],
            {(PUT_MUG, "place Mug -> CoffeeMachine")},
        ),
    ],
)
def test_connectives_and_references(text, tasks, order):
    assert read(text) == (tasks, order, [])


@pytest.mark.parametrize(
    "text, task",
    [
        # sources and landmarks: the place after "from (in) between / under" says where the object is
        (
            "move the plunger from between the sink and toilet to the cabinet underneath the sink",
            "place Plunger -> Cabinet",
        ),
        (
            "move the plunger from in between the sink and the toilet to the cabinet",
            "place Plunger -> Cabinet",
        ),
        # descriptive names
        ("put the watch in the clothing cabinet", "place Watch -> Dresser"),
        ("place the soap on the toilet basin", "place SoapBar -> Toilet"),
        ("place a watch in a safe box", "place Watch -> Safe"),
        ("put the tea pot on the counter", "place Kettle -> CounterTop"),
        # plurals and pieces
        ("put the keychains in the drawer", "place_two 2x KeyChain -> Drawer"),
        ("put a set of keychains in the drawer", "place KeyChain -> Drawer"),
        ("put the keys in the drawer", "place KeyChain -> Drawer"),
        ("throw both pieces of soap in the garbage can", "place_two 2x SoapBar -> GarbageCan"),
        ("put a piece of apple in the fridge", "place Apple(sliced) -> Fridge"),
        ("put one of the apples in the fridge", "place Apple -> Fridge"),
        # a container stated by a relative clause; one more stop on the way
        ("put a mug that's got a pencil in it on the desk", "place_in_container Pencil in Mug -> Desk"),
        (
            "move soap from the counter to the sink, followed by moving to the cabinet",
            "clean_place SoapBar -> Cabinet",
        ),
        # navigation and finding are steps of the task
        ("go to the counter, grab the bread and put it in the fridge", "place Bread -> Fridge"),
        ("locate the egg and put it in the fridge", "place Egg -> Fridge"),
        # the lamp a person uses lights what they look at
        ("use the light from the lamp to look at the mug", "examine_in_light Mug under DeskLamp"),
    ],
)
def test_landmarks_names_plurals_and_steps(text, task):
    tasks, _, unparsed = read(text)
    assert (tasks, unparsed) == ([task], [])
    assert account(text, parse_instruction(text, ROOM, "room").tasks, []) == []


def spec(kind: str, obj: str, rec: str, tid: str = "A", count: int = 1) -> BaseTaskSpec:
    return BaseTaskSpec(id=tid, kind=kind, object=[obj], receptacle=[rec], count=count)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    "text, tasks, before, unread",
    [
        # "next to" names a place, not a step; a real sequence word still needs an order
        (
            "put the mug in the sink next to the egg and put the pen in the fridge",
            ["Mug:SinkBasin", "Pen:Fridge"],
            [],
            [],
        ),
        (
            "put the mug on the counter, next put the egg in the fridge",
            ["Mug:CounterTop", "Egg:Fridge"],
            [],
            ["next"],
        ),
        (
            "put the mug on the counter and the egg in the fridge, in that order",
            ["Mug:CounterTop", "Egg:Fridge"],
            [],
            ["in that order"],
        ),
        # "clean up" tidies; "clean" still needs a washing task
        ("clean up the pencils and put them on the desk", ["Pencil:Desk:2"], [], []),
        ("clean the mug and put it on the desk", ["Mug:Desk"], [], ["clean"]),
        # finding is a step only before what is done with the object
        ("find the mug and put it in the sink", ["Mug:SinkBasin"], [], []),
        (
            "put the egg in the fridge, then find the keys",
            ["Egg:Fridge", "KeyChain:Fridge"],
            [("A", "B")],
            ["find"],
        ),
        # "a clear bowl" describes the bowl; "clear the counter" is a request no task does
        ("put a clear mug in the sink", ["Mug:SinkBasin"], [], []),
        ("clear the desk and put the mug in the sink", ["Mug:SinkBasin"], [], ["desk", "clear"]),
        # where the robot walks is a step; a place nothing goes to is still named
        ("walk over to the sink and put the mug in it", ["Mug:SinkBasin"], [], []),
        ("put the mug in the sink and the egg in the drawer", ["Mug:SinkBasin"], [], ["egg", "drawer"]),
        # "when" orders ("... when you're done"): two tasks and no order is unread, never a silent guess
        (
            "put the mug in the sink and the pen in the drawer when you can",
            ["Mug:SinkBasin", "Pen:Drawer"],
            [],
            ["when"],
        ),
        # a piece of soap is a whole bar; a piece of bread is a slice
        ("put both pieces of soap in the sink", ["SoapBar:SinkBasin:2"], [], []),
        ("put both pieces of bread in the sink", ["Bread:SinkBasin:2"], [], ["pieces"]),
    ],
)
def test_check_one_accepts_what_is_used_and_names_the_rest(text, tasks, before, unread):
    specs = []
    for k, t in enumerate(tasks):
        obj, rec, *n = t.split(":")
        count = int(n[0]) if n else 1
        specs.append(spec("place_two" if count == 2 else "place", obj, rec, chr(65 + k), count))
    assert [u.words for u in account(text, specs, before)] == unread


@pytest.mark.data
# users_casual (3.2 s CPU) is the same check on a larger set: `sweep` (docs/reliability.md, rule 3)
@pytest.mark.parametrize(
    "name, least", [("users", 50), pytest.param("users_casual", 235, marks=pytest.mark.sweep)]
)
def test_user_style_set_converts(name, least):
    """No line of a user-style set is read wrong; a line that must be refused is; 90 % of the rest convert."""
    import trust_sets

    gts = trust_sets.load(name)  # the rows as the all-sets check loads them: one reading of each per process
    outcomes = [trust_sets.outcome(gt)[0] for gt in gts]
    assert len(gts) >= least
    assert [gt.instruction for gt, what in zip(gts, outcomes, strict=True) if what == "wrong"] == []
    feasible = [what for gt, what in zip(gts, outcomes, strict=True) if gt.feasible]
    assert feasible.count("converted") >= 0.9 * len(feasible)


# wrong readings a set found and left to a later branch. h159's held-out (read so on main too): "carry X
# to the desk and switch on the lamp" is read as a placing and a switching, not an examination under the
# desk's lamp (the drafts' class): every word names something a task uses, so check 1, which counts per
# mention since h172, has nothing to name
KNOWN_WRONG: set[str] = {
    # h239's held-out half (scored once, read so on main too): "both knives go in a drawer" after a treated
    # list is read as a place_two of its own beside three treatments with no place (places-after class)
    "Wash a mug, a butter knife and a knife. The mug goes on the coffee machine, and both knives go in a "
    "drawer.",
    # h166's paper-style dev: its truth orders "do the same with Y" after its task, which no word says
    "Put a remote in a box and set the box on the armchair, and move two sets of keys to the sofa. Then grab "
    "the watch on the table, turn on the floor lamp, and do the same with the remote control.",
    # h183's dev set: its truths order "then" after the last clause only; "A and B, then C" (one clause of
    # two tasks) the reader keeps after both, as the guide leaves it open (h213 read "A, B, then C" as [B, C])
    "put two remotes on the couch and two credit cards on it too, then put two remotes on the armchair "
    "and after that one more remote on the sofa",
    "put 2 sponges in the bathtub and 2 tissue boxes in the drawer. then throw a tissue box in the trash, "
    "and lastly wash a sponge and put it in the drawer",
    # h183's held-out half (scored once, read so on main too): the same three-way convention
    "put both keys on the shelf and the vase on the coffee table. then put a remote on the armchair and "
    "after that two more remotes on it",
    # h180's paper-style dev: its truth (two trials) keeps "put the box on the couch" a task beside "then drop
    # a remote into it"; the rules read one place_in_container, the guide's "usually ONE ALFRED task"
    "Hold a remote and turn on the floor lamp. After that, put the box on the couch and then drop a second "
    "remote into it.",
    # h180's held-out half (scored once, read wrong on main too): the same box class twice ("set both of them
    # on the table" after a mug and a bowl is read since h212)
    "Move the box from the table to the couch and put a remote in it. Turn on the floor lamp while holding "
    "another remote.",
    "Examine a remote and then a credit card under the floor lamp. Put the box on the couch, and then put "
    "another remote in it.",
    # h178's held-out paper-style set (results/language/h178.md), read wrong at the session-28 end (the laptop
    # carried to the lamp reads right since h190): "two pencils in that same drawer afterwards" (the order)
    "Could you put two pens in a dresser drawer, and two pencils in that same drawer afterwards? Before "
    "you do any of that, move two phones from the dresser to the bed, and put two alarm clocks on the "
    "bookshelf at any point.",
    # h195's held-out half (scored once at efb6c7c5): "then" over "A and the box on B, oops i mean C, and D"
    # (the correction's comma), and "when you finish all" closing a clause after two "then"s is not read as
    # "finally" (the hand towel after the cloths)
    "look at the remote under the floor lamp, then put the watch in a box and the box on the dining table, "
    "oops i mean the coffee table, and put a credit card in a box on the dresser",
    "you throw two spray bottle in garbage, then two cloth put on side table, then two soap bar in bathtub, "
    "and hand towel put in bathtub when you finish all",
    # h189's held-out set: "plus X on Y" reads Y as X's destination (users_h154's "plus" lists need it); Y
    # is where the bottles are, which only the next sentence ("Once those are in") tells (h218)
    "Throw two bars of soap from the counter into the bin by the toilet, plus the two spray bottles on the "
    "back of the toilet. Once those are in, rinse the pink bar of soap between the sinks and throw it in "
    "the bin as well.",
    # h203's held-out set, scored once at 13e17269: "A and do the same with B. Then C" orders C after A, B
    # (the grammar's convention for "then" after a sentence of two tasks); the guide's "then": after B only
    "Look at the box on the table under the desk lamp and do the same with the plate on the little brown "
    "table. Then look at the credit card on the TV stand under the floor lamp.",
    # h216's held-out half (scored once at 8d9ada15, read so on main too): "plus two heads of lettuce in the
    # fridge too" after "a potato slice in a pan and the pan in the fridge" puts the lettuce in the pan
    "Wash a slice of apple and put it on the dining table. Put a potato slice in a pan and the pan in the "
    "fridge, plus two heads of lettuce in the fridge too. Don't forget to chill a tomato slice and put it in "
    "the microwave.",
    # h221's held-out plain-user set (scored once at 2c331250, read so at the session-30 start too): "after
    # that" after "A and B" orders C after both (the grammar's convention; the guide's: after B only)
    "wash a sponge and put it in the drawer and put two cloths in there too and after that put 2 sponges in "
    "the tub",
    "chill a slice of lettuce and put it on the table and put a butter knife in a pan and put the pan on the "
    "counter after that heat an apple and throw it in the trash",
    # h219's dev set: "put the pen in a mug, leaving the mug on the desk" reads the participle as a third task
    # (a movable container said with "leaving", h212's class)
    "Move the two alarm clocks from the desk at the foot of the bed to the dresser, and put the pen on the "
    "desk in a mug, leaving the mug on the desk.",
    # h219's held-out set, scored once at ffb36763, no rule tuned: "the candle at the back corner of the
    # counter on the toilet tank" takes the counter (a part of it said with "at") as the destination
    "In the bathroom, move the yellow rag in the sink to the tub, put the candle at the back corner of the "
    "counter on the toilet tank, and put the two toilet paper rolls, one on the back of the toilet and the "
    "other by the sink, in the drawer.",
    # h213's dev set: "first A, then heat B, heat C, then D": C has no order word (the guide), but the
    # reader restates a list's shared verb ("After that, wash these: X, Y and Z", paper_h204dev), so a
    # clause with the verb of the one before it stays in the "then" step
    "first rinse the pan and put it on the stove, then heat the cup and put it on the counter, heat the "
    "plate and put it on the counter, then put the tomato in the microwave",
    # h195's dev set: "then like put a credit card in a box ..., uh, put both statues on the dresser too, and
    # finally ...": the statues' clause has the verb of the one before it (the same-verb class, h213)
    "um okay so, look at the remote under the floor lamp, then like put a credit card in a box and put the "
    "box on the dresser, uh, put both statues on the dresser too, and finally the watch in a box on the "
    "dining table",
    # h213's held-out half (scored once at the end): "then B, and put C ... too": C a clause of its own by the
    # guide (no order), but the reader restates a shared verb the same way ("look at the pen and the watch"),
    # so ", and <the same verb>" after a "then" clause stays after the task before "then"
    "rinse the cloth and put it in the cabinet. then put the spray bottle on the toilet, and put the plunger "
    "in the cabinet too.",
    "rinse the pan and put it in the fridge. then rinse the spatula and put it on the counter, and rinse the "
    "plate and put it in the cabinet too.",
    # and two more of the class since 221d542a (a comma-joined clause of the same verb, for paper_h204dev)
    "rinse the bowl and put it in the microwave, then chill the egg and put it in the microwave, chill the "
    "cup and put it in the sink, and finally chill the mug and put it on the coffee machine",
    "first chill the tomato and put it on the dining table, then chill the mug and put it on the coffee "
    "machine, chill the apple and put it on the dining table, then chill the bread and put it on the dining "
    "table",
    # h224's held-out half (scored once at b8655f74, read so at the branch point too): "then" covers the
    # clauses after it in its sentence, and "A, B, then C" is a sequence (the guide: the next clause only)
    "look at the box under the desk lamp, then put the phone in the same box and put it on the side table, "
    "and put two vases on that side table too",
    # h227's held-out near misses (scored once, read so on main before the branch too): a verbless count
    # after a placing moves the apple to the sink (a negation's "it" reads its place since h236)
    "put the apple in the fridge two in the sink",
    # h232's held-out plain-user set (scored once at 2dd9619e): a verbless item before "then" ("A and one on
    # the sofa then C") keeps C after both, as four committed truths write it (users_h147dev, h154dev/held);
    # these three truths follow the guide's "immediately preceding clause" (h243 reads the clause form so)
    "put 2 credit cards on the armchair and one on the sofa then put two remotes on the sofa too",
    "put 2 toilet papers on the counter and one hand towel in the bath tub and when ur done put 2 hand "
    "towels in the tub",
    "ok so put a remote on the couch and 2 remotes on the coffee table and then a credit card on the couch "
    "and after that 2 credit cards on the armchair thanks",
    # h231's held-out set (scored once at 0dc0756a, no rule changed): a landmark taken as the destination;
    # one task split in two (a pointed-at source, "a slice on the plate and the plate on …"); its split
    # treatments and "both slices" read right since h247 (treated_lists)
    "Both bars of soap on the back of the toilet need to be thrown in the green bin.",
    "That alarm clock on the dresser - grab it and look at it under the desk lamp.",
    "Cut up a lettuce, put a slice on the blue plate and set the plate on the table.",
    # h249's held-out set (scored once at db2419d0, no rule changed): an order said by naming tasks
    # ("any order" over a numbered list, "Zoe does hers first", "do 1 n 2 first", "once" over two clauses),
    # "chill that too" read as heating, a destination carried over, a verbless list under one destination
    "Closing checklist (any order): 1) heat the potato from the fridge and throw it in the green bin 2) fork "
    "in the green cup, cup on the counter",
    "Chore chart, Sunday. Zoe: wash the spatula next to the sink and lay it on the white table. Finn: rinse a"
    " slice of potato and leave it on the counter. Zoe again: chill the head of lettuce from the white table "
    "and put it on the counter. Zoe does hers first.",
    "Would you wash the tea kettle from the stove and put it on the counter by the coffee maker? Then could "
    "you chill the tomato next to the microwave and put it in the microwave? And the frying pan - chill that "
    "too and put it away in the lower cupboard beside the fridge, please.",
    "hey! 4 things pls: 1) heat an apple slice n put it in the fridge 2) tomato slice in a pot, pot in the "
    "fridge 3) butter knife in a wine glass, glass on the counter 4) chill a lettuce slice n leave it on the "
    "white table. do 1 n 2 first, 3 n 4 after",
    "For the white table: a chilled slice of tomato, the spatula in the pot from the stove with the pot on "
    "the table, the green sponge on a blue plate with the plate on the table, and the white egg once it's "
    "been washed. Egg last.",
    "Could you chill the big pot from the front left burner and set it on the white table? Put a potato slice"
    " in the other pot and put that in the fridge. A pair of potatoes go in the sink, and a heated tomato "
    "goes on the white table once the pot is there.",
    # h238's held-out (scored once at a180ac6d, wrong at the branch point too): a slicing said in a sentence
    # of its own (";") before "a pot with an apple slice in it" stays a set_state task of its own
    "Cut an apple; a pot with an apple slice in it should end up on the table.",
    # h237's held-out: "after that" inside a repeat's fragment, before its "but ..." place, orders nothing
    "Heat a slice of bread and put it in the fridge. Do the same with an egg after that, but leave it on the "
    "counter.",
    # h234's held-out remarks (scored once): the order is read; "the knife" of FloorPlan26 read as ButterKnife
    "Wash the knife and put it on the dining table, chill the lettuce and put it on the dining table, and "
    "warm up the mug and put it on the coffee machine. Do the lettuce once the others are finished.",
    # h242's dev half, left (read so on main too, none the new rules' shape): "microwave X" with no place read
    # as a placing in the microwave (the structure model); "and the tomato too, but on the counter" keeps
    # the place, not the chilling; "First A, and then B" inside one task still orders A before what follows
    "Microwave the potato, then drop the tomato in the sink.",
    "Chill the lettuce and put it in the sink, and the tomato too, but on the counter.",
    "First heat the potato, and then put it in the fridge. Chill the apple and put it in the microwave.",
    # h266's held set (paper_h266held; scored once, results/language/h266.md): "A ... goes on the table
    # afterwards" after two container pairs orders it after the last pair only
    "Put a lettuce slice on a plate and put the plate in the fridge. Put an apple slice in a pot and the pot "
    "on the counter. A chilled bread slice goes on the table afterwards.",
    # h271's held-out plain-user set (scored once at 278391fe, results/language/h271.md): "all the" and "the
    # rest of the" counted as every one the world holds (the guide: 2 for a pick-two); "the table at the end
    # of the bed" read as the side table ("A, before that B", read as A before B, is read right since h277)
    "put a pen in a cup and put it on the table at the end of the bed, oh and both books go there too",
    "put all the spray bottles in the cabinet under the sink and wash a cloth and put it on the toilet",
    "put 2 soap bottles and a spray bottle on the toilet. the rest of the spray bottles go in the cabinet",
    # h285's held-out set (paper_h285; scored once at 88e8a7c7, results/language/h285.md): "it" after a plural
    # taken as the clocks, not the racket; "after that" after a gapped "and two pencils there too" orders
    # both tasks (the truth: the clause's one) ("hack number one ... number two", read as an order, is
    # h294's: a label gives no order)
    "Put the tennis racket on the desk, and move two alarm clocks from the desk to the dresser. Before the "
    "racket goes on the desk, look at it under the desk lamp.",
    "Put the alarm clock on the desk and two pencils there too, and after that look at a pillow under the "
    "lamp.",
    # (h284's three wrong lines of users_h284 read right or are refused by name since h293)
    # (h307: "put a glass of wine on the dining table" and "Put the apple in the fridge. Later, Bread", read
    # wrong at exit 0 before, are refused by name now)
    # h307's held-out trust set (trust/trust_h307held, scored once at 13a5f56d): "water" after a glass is
    # read as washing it (clean_place), wrong before and after h307's rules
    "Place a glass of water on the counter top",
    # h300's held-out plain-user set (users_h300, scored once at 8874c89c, results/language/h300.md):
    # "once both mugs are done" lost an order; a verbless list ("Please: X in Y and Y on Z") split tasks
    # (since h309 refused or partial by name; its other three lines read right, "armchair: ..." since h315)
    "chill one mug and put it under the coffee maker, heat another mug and put it there too. throw away a "
    "warm slice of apple once both mugs are done",
    "Please: knife in mug and mug on table, sponge on blue plate and plate on table, cold apple in sink, and "
    "clean egg in garbage. Order does not matter.",
    # h301's held-out set (paper_h301; scored once at 8874c89c, results/language/h301.md): a landmark
    # ("beside the bread") read as what is washed (h310: now partial, its "Clause 4.1" heading unread)
    "Clause 4.1. The Contractor shall wash the spoon found on the counter beside the bread and shall "
    "thereafter place the said spoon upon the microwave stand. Time is of the essence.",
    # the retrained models of session 35 (h309's lexicon names changed their training data): "heat an egg and
    # put it on the counter first" after a sentence of its own is ordered after it (users_h183held);
    # paper_h301's "..., but they can wait till you've done the lamp", read with no order, is refused by name
    # since check 1 counts "till" and a held thing's "while" frees no order
    "clean the bowl and put it in the microwave. heat an egg and put it on the counter first",
}


@pytest.mark.sweep
@pytest.mark.data
@pytest.mark.parametrize(
    "name", sorted(p.stem for p in (Path(__file__).parent / "data" / "styles").glob("*.txt"))
)
def test_no_committed_style_set_is_read_wrong(name):
    """Every style set at once (`-m sweep`): a change to a shared rule may read another helper's line
    otherwise than its ground truth says (session 22: the one-slip respelling read three lines marked as
    refusals), which the per-set tests, each asserting its own set, do not all see."""
    import trust_sets

    wrong = [gt.instruction for gt in trust_sets.load(name) if trust_sets.outcome(gt)[0] == "wrong"]
    assert set(wrong) <= KNOWN_WRONG, wrong


@pytest.mark.data
def test_a_line_is_read_once_for_each_question(monkeypatch):
    """The language folder's `one_reading_per_line` (conftest): the all-sets check and the per-set tests
    share a line's reading, and a verdict still follows the truth and the plural mode it was asked with (the
    trials: test_style_trials.py)."""
    import trust_sets

    reads: list[str] = []
    translate = trust_sets.translate

    def counted(text, *args, **kwargs):
        reads.append(text)
        return translate(text, *args, **kwargs)

    monkeypatch.setattr(trust_sets, "translate", counted)
    line = "FloorPlan1 | put the plates in the sink | place_two Plate SinkBasin x2 | "
    gt, other = (
        trust_sets.GTInstance.model_validate(trust_sets.parse_line(ln, "read_once", 1))
        for ln in (line, line.replace("SinkBasin", "Fridge"))
    )
    assert [trust_sets.outcome(gt)[0] for _ in range(2)] == ["refused"] * 2  # "ask": how many plates?
    assert [trust_sets.outcome(gt, plurals="two")[0] for _ in range(2)] == ["converted"] * 2
    assert trust_sets.outcome(other, plurals="two")[0] == "wrong"  # its own truth, read again
    assert reads == ["put the plates in the sink"] * 3
