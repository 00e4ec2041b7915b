#include "core/household/persona_generator.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/common/json_check.hpp"
#include "core/common/rng.hpp"
#include "core/common/text.hpp"

namespace socsim::household {
namespace {

// ---- curated parts (written for socsim) ----

struct Culture {
  std::vector<const char*> female, male, surnames;
};

const std::vector<Culture>& cultures() {
  static const std::vector<Culture> all = {
      {{"Ingrid", "Solveig", "Astrid", "Liv", "Karin", "Freja", "Sigrid", "Maja"},
       {"Erik", "Lars", "Nils", "Magnus", "Henrik", "Anders", "Sven", "Jonas"},
       {"Lindgren", "Bergstrom", "Dahl", "Nyberg", "Sandvik", "Aasen", "Holmberg", "Eklund"}},
      {{"Giulia", "Francesca", "Chiara", "Elena", "Marta", "Lucia", "Sofia", "Carla"},
       {"Marco", "Luca", "Paolo", "Giorgio", "Matteo", "Enzo", "Stefano", "Davide"},
       {"Rossi", "Esposito", "Conti", "Marino", "Greco", "Lombardi", "Ferri", "Galli"}},
      {{"Adaeze", "Chiamaka", "Ngozi", "Amina", "Folake", "Yetunde", "Efua", "Akosua"},
       {"Chinedu", "Emeka", "Tunde", "Kwame", "Kofi", "Yaw", "Olumide", "Babajide"},
       {"Okonkwo", "Adeyemi", "Nwosu", "Boateng", "Asante", "Owusu", "Eze", "Balogun"}},
      {{"Mei", "Xiu", "Lan", "Jing", "Yan", "Hui", "Ling", "Fang"},
       {"Wei", "Jun", "Hao", "Lei", "Bo", "Ming", "Tao", "Chen"},
       {"Zhang", "Wang", "Liu", "Huang", "Zhao", "Zhou", "Sun", "Ma"}},
      {{"Aiko", "Haruka", "Naomi", "Emi", "Rin", "Yui", "Keiko", "Sayaka"},
       {"Hiroshi", "Takeshi", "Ren", "Daichi", "Kaito", "Shota", "Kenta", "Makoto"},
       {"Tanaka", "Sato", "Kobayashi", "Yamamoto", "Inoue", "Kimura", "Hayashi", "Shimizu"}},
      {{"Ananya", "Kavya", "Meera", "Divya", "Lakshmi", "Pooja", "Sunita", "Nisha"},
       {"Arjun", "Rohan", "Vikram", "Sanjay", "Rahul", "Karthik", "Anil", "Dev"},
       {"Iyer", "Sharma", "Nair", "Reddy", "Menon", "Patel", "Kapoor", "Joshi"}},
      {{"Fatima", "Layla", "Yasmin", "Salma", "Rania", "Huda", "Mariam", "Nadia"},
       {"Karim", "Youssef", "Tariq", "Samir", "Nabil", "Rami", "Bilal", "Khalid"},
       {"Haddad", "Mansour", "Nasser", "Khoury", "Saleh", "Aziz", "Farouk", "Darwish"}},
      {{"Camila", "Valentina", "Lucia", "Ximena", "Paula", "Daniela", "Gabriela", "Renata"},
       {"Diego", "Javier", "Andres", "Santiago", "Emilio", "Tomas", "Pablo", "Joaquin"},
       {"Gomez", "Herrera", "Castillo", "Rojas", "Vargas", "Mendoza", "Navarro", "Ortega"}},
      {{"Aleksandra", "Zofia", "Katarzyna", "Agnieszka", "Ewa", "Natalia", "Irena", "Milena"},
       {"Piotr", "Tomasz", "Marek", "Pawel", "Jakub", "Krzysztof", "Bartek", "Grzegorz"},
       {"Kowalski", "Wisniewski", "Zielinski", "Lewandowski", "Wojcik", "Kaminski", "Mazur", "Krawczyk"}},
      {{"Siobhan", "Niamh", "Ciara", "Roisin", "Eileen", "Maeve", "Orla", "Brid"},
       {"Cian", "Padraig", "Declan", "Eoin", "Ronan", "Fergal", "Seamus", "Donal"},
       {"Gallagher", "Doherty", "Kennedy", "Byrne", "Walsh", "Quinn", "Regan", "Moran"}},
      {{"Emily", "Hannah", "Rebecca", "Sarah", "Laura", "Claire", "Megan", "Alice"},
       {"James", "Thomas", "Daniel", "Oliver", "Samuel", "Peter", "Michael", "Harry"},
       {"Fletcher", "Barker", "Turner", "Hughes", "Marsh", "Porter", "Webb", "Lawson"}},
      {{"Ayse", "Elif", "Zeynep", "Derya", "Selin", "Emine", "Gul", "Melike"},
       {"Mehmet", "Emre", "Burak", "Murat", "Cem", "Onur", "Kerem", "Serkan"},
       {"Yilmaz", "Demir", "Kaya", "Celik", "Aydin", "Ozturk", "Arslan", "Dogan"}},
  };
  return all;
}

// An occupation with the hours, sleep times and worries that go with it. Text placeholders:
// {F} first name, {p}/{P} subject pronoun, {pp}/{PP} possessive, {po} object pronoun, {X} a
// per-occupation variant.
struct Occupation {
  const char* key;
  std::vector<const char*> keywords;  // for the occupation constraint
  WorkPattern pattern;
  int min_age, max_age;
  std::vector<const char*> variants;  // {X}
  const char* text;
  int bed_lo, bed_hi, wake_lo, wake_hi;  // minutes after 00:00; bedtimes after midnight ≥ 1440
  bool day_sleeper = false;              // night shift: sleeps 8 am – 3 pm after a shift
  std::vector<const char*> thoughts;
  const char* habit = "";  // lifestyle phrase tied to the work ("" = none)
};

const std::vector<Occupation>& occupations() {
  static const std::vector<Occupation> all = {
      {"night nurse",
       {"nurse", "nursing", "hospital", "night shift"},
       WorkPattern::kNightShift,
       23,
       62,
       {"surgical ward", "maternity ward", "intensive care unit"},
       "{F} is a nurse on the {X} who works the night shift from 7 pm to 7 am, three nights a week.",
       1440,
       1470,
       450,
       510,
       true,
       {"{F} is studying for a specialist certificate and fits the reading in between shifts.",
        "{F} wonders whether {p} should move to day shifts before winter comes."},
       "{P} keeps blackout curtains in the bedroom and meal-preps in batches on {pp} days off"},
      {"night security guard",
       {"security", "guard", "night shift", "watchman"},
       WorkPattern::kNightShift,
       25,
       64,
       {"a shopping centre", "the city hospital", "a data centre"},
       "{F} is a security guard at {X} and works the night shift from 10 pm to 6 am, Monday to Friday.",
       1440,
       1470,
       450,
       510,
       true,
       {"{F} is reading a thick history book on the quiet nights and is halfway through it.",
        "{F} is trying to get enough daylight on {pp} days off."},
       "{P} drinks strong coffee before leaving and solves crossword puzzles on breaks"},
      {"warehouse night worker",
       {"warehouse", "logistics", "night shift", "forklift"},
       WorkPattern::kNightShift,
       19,
       58,
       {"a supermarket chain", "an online shop", "a parcel company"},
       "{F} drives a forklift in the warehouse of {X} and works the night shift from 11 pm to 7 am, Sunday "
       "to Thursday.",
       1440,
       1500,
       480,
       540,
       true,
       {"{F} is saving for a used car and counts every overtime hour.",
        "{F} wants to get the forklift instructor licence."},
       ""},
      {"line cook",
       {"cook", "chef", "restaurant", "kitchen"},
       WorkPattern::kEveningShift,
       19,
       55,
       {"a busy trattoria", "a noodle bar", "a hotel restaurant"},
       "{F} is a line cook at {X} and works the evening shift from 3 pm to 11 pm, Wednesday to Sunday.",
       1470,
       1530,
       540,
       600,
       false,
       {"{F} dreams of a small food truck and tests sauces at home.",
        "{F} is tired of the late nights but loves the rush of service."},
       "{P} cooks elaborate brunches on {pp} days off"},
      {"bartender",
       {"bartender", "bar", "barista", "pub"},
       WorkPattern::kEveningShift,
       21,
       45,
       {"a cocktail bar", "a jazz club", "a student pub"},
       "{F} is a bartender at {X} and works the evening shift from 5 pm to 1 am, Thursday to Monday.",
       1560,
       1590,
       600,
       660,
       false,
       {"{F} is inventing a signature cocktail for a competition.",
        "{F} wonders whether {p} should go back to college."},
       ""},
      {"accountant",
       {"accountant", "accounting", "finance", "auditor", "bookkeeper"},
       WorkPattern::kCommute,
       24,
       64,
       {"an audit firm", "a shipping company", "the city council"},
       "{F} is an accountant at {X} in the city centre and works from 8:30 am to 5 pm.",
       1350,
       1410,
       390,
       420,
       false,
       {"{F} is buried in the year-end closing and counting the days to the holidays.",
        "{F} is thinking about taking the chartered accountant exam next year."},
       "{P} keeps the household accounts in a neat ledger"},
      {"primary teacher",
       {"teacher", "teaching", "school teacher", "educator"},
       WorkPattern::kCommute,
       24,
       64,
       {"a primary school", "a village school", "a bilingual school"},
       "{F} is a teacher at {X} and works from 7:30 am to 4 pm, grading homework at home in the evenings.",
       1320,
       1380,
       360,
       390,
       false,
       {"{F} is preparing the class for the school play and sewing costumes at night.",
        "{F} has a parents' evening on Thursday and thirty reports to write."},
       ""},
      {"electrician",
       {"electrician", "tradesman", "builder", "construction", "plumber"},
       WorkPattern::kCommute,
       20,
       63,
       {"a small building firm", "the housing association", "a solar installer"},
       "{F} is an electrician for {X} and works from 7 am to 3:30 pm.",
       1290,
       1350,
       345,
       375,
       false,
       {"{F} is thinking about starting {pp} own business next year.",
        "{F} is rewiring the spare room at home on weekends."},
       "{P} keeps {pp} tools neatly sorted in the hallway cupboard"},
      {"bus driver",
       {"driver", "bus", "transport", "tram"},
       WorkPattern::kCommute,
       25,
       64,
       {"the early route", "the airport line", "the night-owl express"},
       "{F} drives a city bus on {X} and works from 6 am to 2 pm.",
       1260,
       1290,
       285,
       315,
       false,
       {"{F} is saving for a trip to visit {pp} cousins abroad.",
        "{F} would like to switch to the later route next year."},
       ""},
      {"shop assistant",
       {"shop", "retail", "sales", "cashier", "store"},
       WorkPattern::kCommute,
       18,
       66,
       {"a garden centre", "a bookshop", "a hardware store"},
       "{F} works at {X} from 9 am to 5:30 pm, Tuesday to Saturday.",
       1350,
       1410,
       420,
       450,
       false,
       {"{F} has been asked to run the shop's new online orders and feels unsure about it.",
        "{F} is looking forward to the summer sale being over."},
       ""},
      {"software developer",
       {"software", "developer", "programmer", "engineer", "it"},
       WorkPattern::kRemote,
       22,
       60,
       {"a company abroad", "a health-care startup", "a game studio"},
       "{F} is a software developer who works remotely for {X}.",
       1410,
       1470,
       450,
       510,
       false,
       {"{F} is debugging a stubborn memory leak and dreams about it at night.",
        "{F} is wondering whether to take a proper holiday without a laptop."},
       ""},
      {"support lead",
       {"customer support", "call centre", "support", "customer service"},
       WorkPattern::kRemote,
       22,
       62,
       {"an insurance company", "an internet provider", "a travel agency"},
       "{F} leads a customer support team for {X} and works from home.",
       1350,
       1410,
       390,
       435,
       false,
       {"{F}'s team is short-staffed this week and {p} is covering extra calls.",
        "{F} is training two new colleagues over video."},
       ""},
      {"translator",
       {"translator", "translation", "writer", "language"},
       WorkPattern::kFreelance,
       24,
       70,
       {"technical manuals", "children's books", "legal contracts"},
       "{F} is a freelance translator of {X}.",
       1380,
       1470,
       420,
       480,
       false,
       {"{F} has a big translation due on Friday and is behind by twenty pages.",
        "{F} is looking for steadier clients."},
       "{P} drinks endless cups of tea at {pp} desk"},
      {"graphic designer",
       {"designer", "graphic", "illustrator", "artist"},
       WorkPattern::kFreelance,
       22,
       60,
       {"a desk in the living room", "a corner of the bedroom", "the kitchen table"},
       "{F} is a freelance graphic designer who works from {X}.",
       1440,
       1500,
       480,
       540,
       false,
       {"{F} is designing a logo for a bakery and has thrown away ten drafts.",
        "{F} is waiting for two invoices to be paid."},
       "{P} sketches in a notebook wherever {p} goes"},
      {"project manager",
       {"manager", "project manager", "office", "hybrid"},
       WorkPattern::kHybrid,
       27,
       63,
       {"Mondays and Thursdays", "Tuesdays and Fridays", "Wednesdays and Fridays"},
       "{F} is a project manager at an engineering company on a hybrid schedule, working from home on {X} "
       "and at the office on the other weekdays.",
       1350,
       1410,
       390,
       420,
       false,
       {"{F} is juggling three deadlines and a difficult client.",
        "{F} is planning the team's summer outing."},
       ""},
      {"civil servant",
       {"civil servant", "administrator", "clerk", "government", "hybrid"},
       WorkPattern::kHybrid,
       25,
       65,
       {"Tuesdays and Thursdays", "Mondays and Wednesdays", "Fridays"},
       "{F} is a clerk at the tax office on a hybrid schedule, working from home on {X} and at the office on "
       "the other weekdays.",
       1350,
       1410,
       390,
       435,
       false,
       {"{F} is reorganising the archive and secretly enjoys it.",
        "{F} is counting the weeks to a long holiday."},
       ""},
      {"university student",
       {"student", "university", "college", "studies"},
       WorkPattern::kCollege,
       18,
       27,
       {"biology", "history", "mechanical engineering", "economics", "music"},
       "{F} is a second-year student of {X} at the university with lectures most weekdays.",
       1440,
       1530,
       480,
       540,
       false,
       {"{F} has exams in three weeks and has not started revising.",
        "{F} is thinking about a semester abroad."},
       "{P} lives on pasta and instant coffee"},
      {"phd student",
       {"phd", "doctoral", "researcher", "thesis", "student"},
       WorkPattern::kCollege,
       24,
       35,
       {"chemistry", "linguistics", "climate science", "mathematics"},
       "{F} is a PhD student in {X} at the university who is writing up {pp} thesis.",
       1440,
       1500,
       450,
       510,
       false,
       {"{F}'s thesis chapter is overdue and {pp} supervisor is asking about it.",
        "{F} is applying for postdoc positions."},
       ""},
      {"retiree",
       {"retired", "retiree", "pensioner"},
       WorkPattern::kRetired,
       63,
       92,
       {"postman", "school teacher", "nurse", "engineer", "shopkeeper", "librarian"},
       "{F} is a retired {X}.",
       1290,
       1380,
       360,
       450,
       false,
       {"{F} is waiting for the grandchildren's visit and has baked far too much.",
        "{F} worries a little about {pp} knee and the stairs.",
        "{F} is writing down family recipes for the grandchildren."},
       "{P} reads the newspaper cover to cover every morning"},
      {"stay-at-home parent",
       {"stay-at-home", "homemaker", "parent", "carer"},
       WorkPattern::kHomemaker,
       24,
       52,
       {"the house and the children", "two small children", "a toddler and a baby"},
       "{F} is a stay-at-home parent who looks after {X}.",
       1350,
       1410,
       360,
       405,
       false,
       {"{F} misses adult conversation and is thinking about a part-time job.",
        "{F} is potty-training the toddler this week."},
       "{P} cooks all the family meals and does the laundry almost daily"},
      {"job seeker",
       {"job seeker", "unemployed", "between jobs", "looking for work"},
       WorkPattern::kJobSeeker,
       20,
       62,
       {"{pp} contract ended", "the factory closed", "moving to the city"},
       "{F} is between jobs after {X} and is looking for work, sending applications every morning.",
       1410,
       1500,
       450,
       540,
       false,
       {"{F} has an interview next week and is anxious about money.",
        "{F} is taking an online course to retrain."},
       "{P} writes cover letters at the kitchen table"},
      {"office cleaner",
       {"cleaner", "cleaning", "janitor", "split shift"},
       WorkPattern::kSplitShift,
       20,
       64,
       {"offices in the business park", "the university buildings", "a bank headquarters"},
       "{F} cleans {X} on a split shift, from 5:30 am to 9 am and again from 6 pm to 9 pm.",
       1320,
       1350,
       270,
       285,
       false,
       {"{F} is saving to send money to {pp} family.", "{F} is learning English in the afternoons."},
       ""},
      {"baker",
       {"baker", "bakery", "pastry"},
       WorkPattern::kCommute,
       20,
       64,
       {"a family bakery", "the bakery at the market", "a sourdough bakery"},
       "{F} is a baker at {X} and works from 4 am to 12 pm, six days a week.",
       1230,
       1260,
       180,
       195,
       false,
       {"{F} wonders whether {p} will ever open a bakery of {pp} own.",
        "{F} is perfecting a rye bread recipe."},
       "{P} naps in the afternoon after work"},
      {"family doctor",
       {"doctor", "physician", "gp", "medical", "dentist"},
       WorkPattern::kCommute,
       29,
       66,
       {"a health centre", "a village practice", "a children's clinic"},
       "{F} is a family doctor at {X} and works from 8 am to 6 pm, Monday to Thursday.",
       1350,
       1410,
       375,
       405,
       false,
       {"{F} is worried about a patient and keeps thinking about the case.",
        "{F} is organising a charity run for the clinic."},
       ""},
      {"librarian",
       {"librarian", "library", "archivist"},
       WorkPattern::kCommute,
       23,
       66,
       {"the public library", "the university library", "a school library"},
       "{F} is a librarian at {X} and works from 10 am to 6 pm.",
       1410,
       1470,
       450,
       480,
       false,
       {"{F} is planning a reading club for teenagers.",
        "{F} is cataloguing a donated collection of old maps."},
       "{P} reads novels in bed every night"},
      {"mechanic",
       {"mechanic", "garage", "car", "technician"},
       WorkPattern::kCommute,
       19,
       64,
       {"a car repair garage", "the bus depot", "a bicycle shop"},
       "{F} is a mechanic at {X} and works from 7:30 am to 4:30 pm.",
       1320,
       1380,
       360,
       390,
       false,
       {"{F} is restoring an old motorbike and hunting for spare parts.",
        "{F} is thinking about becoming a master mechanic."},
       ""},
      {"piano teacher",
       {"music teacher", "piano", "musician", "teacher"},
       WorkPattern::kFreelance,
       24,
       75,
       {"piano", "violin", "guitar"},
       "{F} is a freelance {X} teacher who gives lessons at home in the afternoons.",
       1380,
       1440,
       450,
       510,
       false,
       {"{F} is preparing {pp} students for the spring recital.",
        "{F} is composing a short piece for a friend's wedding."},
       ""},
      {"content writer",
       {"writer", "journalist", "copywriter", "content writer"},
       WorkPattern::kRemote,
       22,
       60,
       {"a travel magazine", "a software company", "a news website"},
       "{F} is a content writer who works remotely for {X}.",
       1440,
       1530,
       480,
       570,
       false,
       {"{F} has two articles due and a blank page in front of {po}.",
        "{F} is pitching a book idea to a publisher."},
       ""},
      {"pharmacist",
       {"pharmacist", "pharmacy", "chemist"},
       WorkPattern::kCommute,
       25,
       66,
       {"a pharmacy on the high street", "the hospital pharmacy", "a pharmacy in the mall"},
       "{F} is a pharmacist at {X} and works from 8 am to 4:30 pm.",
       1350,
       1410,
       390,
       420,
       false,
       {"{F} is training a new assistant and has little patience left.",
        "{F} is thinking about running a half marathon."},
       ""},
      // Children (household role "child" only).
      {"preschooler",
       {"kindergarten", "preschool", "toddler", "child"},
       WorkPattern::kPreschool,
       3,
       5,
       {"kindergarten"},
       "{F} goes to {X} in the mornings from 8:30 am to 12:30 pm on weekdays.",
       1140,
       1170,
       405,
       435,
       false,
       {"{F} wants to be a firefighter and tells everyone so.", "{F} is learning to write {pp} name."},
       "{P} naps after lunch and needs help brushing {pp} teeth"},
      {"primary pupil",
       {"pupil", "school", "child", "primary school"},
       WorkPattern::kSchool,
       6,
       10,
       {"the primary school around the corner", "the village school", "a bilingual primary school"},
       "{F} is a pupil at {X}.",
       1200,
       1245,
       405,
       435,
       false,
       {"{F} is nervous about a spelling test and practises words at breakfast.",
        "{F} wants a puppy more than anything."},
       ""},
      {"middle schooler",
       {"school", "middle school", "pupil", "child"},
       WorkPattern::kSchool,
       11,
       13,
       {"the middle school", "the school across town", "a music school"},
       "{F} is a pupil at {X} and does homework every afternoon.",
       1260,
       1305,
       390,
       420,
       false,
       {"{F} has a science project due and has turned the desk into a laboratory.",
        "{F} is trying out for the school choir."},
       ""},
      {"high schooler",
       {"high school", "school", "teenager", "student"},
       WorkPattern::kSchool,
       14,
       17,
       {"the high school", "a sports high school", "the grammar school"},
       "{F} is a student at {X} and does homework at {pp} desk most evenings.",
       1320,
       1410,
       375,
       405,
       false,
       {"{F} has a chemistry test on Thursday and a match on Saturday.",
        "{F} is trying to decide what to study after school."},
       ""},
  };
  return all;
}

bool is_child_occupation(const Occupation& o) {
  return o.pattern == WorkPattern::kPreschool || o.pattern == WorkPattern::kSchool;
}

struct Hobby {
  const char* text;
  int min_age, max_age;
};

const std::vector<Hobby>& hobbies() {
  static const std::vector<Hobby> all = {
      {"plays the guitar in the evenings", 12, 90},
      {"knits scarves for the whole family", 14, 95},
      {"bakes bread at weekends", 14, 95},
      {"does yoga before breakfast", 16, 85},
      {"reads crime novels in bed", 13, 95},
      {"keeps houseplants on every windowsill", 16, 95},
      {"plays video games with friends online", 10, 55},
      {"solves crossword puzzles", 16, 99},
      {"paints with watercolours", 10, 95},
      {"sews {pp} own clothes", 16, 90},
      {"plays chess online", 10, 95},
      {"practises the piano every evening", 7, 90},
      {"writes in a journal before sleeping", 12, 95},
      {"builds plastic model kits", 10, 80},
      {"watches football with friends", 14, 85},
      {"cooks big pots of stew for the week", 20, 95},
      {"does a home workout with dumbbells", 16, 70},
      {"grows herbs on the balcony", 18, 95},
      {"meditates every morning", 16, 95},
      {"plays board games with the neighbours", 10, 95},
      {"listens to jazz records", 16, 95},
      {"calls {pp} mother every evening", 18, 75},
      {"goes birdwatching at weekends", 16, 90},
      {"does jigsaw puzzles", 8, 99},
      {"bakes cakes for friends' birthdays", 14, 90},
      {"meal-preps on Sundays", 18, 70},
      {"learns a new language with an app", 12, 85},
      {"plays the violin", 7, 85},
      {"sketches buildings in a notebook", 12, 90},
      {"does the ironing while listening to the radio", 20, 95},
      {"builds with building blocks", 3, 10},
      {"draws with crayons", 3, 9},
      {"plays with {pp} dolls and teddy bear", 3, 8},
      {"plays football in the park after school", 6, 15},
      {"reads comics in bed", 7, 16},
      {"practises the drums after school", 9, 18},
  };
  return all;
}

const std::vector<const char*> kTidyTraits = {"meticulous", "organized", "tidy",         "methodical",
                                              "punctual",   "diligent",  "conscientious"};
const std::vector<const char*> kMessyTraits = {"scatterbrained", "forgetful", "laid-back",
                                               "spontaneous",    "impulsive", "chaotic"};
const std::vector<const char*> kSocialTraits = {"sociable", "outgoing", "talkative",
                                                "cheerful", "friendly", "chatty"};
const std::vector<const char*> kSolitaryTraits = {"introverted", "reserved", "shy", "quiet"};
const std::vector<const char*> kOtherTraits = {
    "curious",    "patient",      "kind",  "stubborn",  "witty",     "calm",       "ambitious", "generous",
    "anxious",    "dry-humoured", "warm",  "practical", "creative",  "determined", "gentle",    "sarcastic",
    "optimistic", "thoughtful",   "loyal", "proud",     "easygoing", "sensitive"};
const std::vector<const char*> kTidyHabits = {"keeps the kitchen spotless",
                                              "tidies up every evening before bed",
                                              "puts everything back where it belongs"};
const std::vector<const char*> kMessyHabits = {"leaves cups all over the house",
                                               "lets the dishes pile up until the weekend",
                                               "can never find {pp} keys"};

struct RoleText {
  HouseholdRole role;
  int min_age, max_age;
  std::vector<const char*> lines;
  std::vector<const char*> thoughts;
};

const std::vector<RoleText>& role_texts() {
  static const std::vector<RoleText> all = {
      {HouseholdRole::kSingle,
       18,
       99,
       {"{P} lives alone in a small flat", "{P} lives on {pp} own with an old cat",
        "{P} lives alone and likes the quiet"},
       {"{F} is thinking about getting a dog for company."}},
      {HouseholdRole::kPartner,
       18,
       99,
       {"{P} lives with {pp} partner, who works long hours", "{P} lives with {pp} partner and their cat",
        "{P} recently moved in with {pp} partner"},
       {"{F} and {pp} partner are planning a trip for their anniversary."}},
      {HouseholdRole::kParent,
       22,
       62,
       {"{P} lives with {pp} partner and their two children", "{P} is raising {pp} teenage son on {pp} own",
        "{P} lives with {pp} partner and their six-year-old daughter"},
       {"{F} is organising a birthday party for {pp} daughter.",
        "{F} worries that the children spend too long on screens."}},
      {HouseholdRole::kChild,
       3,
       17,
       {"{P} lives with {pp} parents and a younger brother", "{P} lives with {pp} mother and grandmother",
        "{P} lives with {pp} parents and an older sister"},
       {}},
      {HouseholdRole::kGrandparent,
       55,
       99,
       {"{P} lives with {pp} spouse and looks after the grandchildren twice a week",
        "{P} lives with {pp} daughter's family and helps with the grandchildren"},
       {"{F} is knitting a blanket for the newest grandchild."}},
      {HouseholdRole::kFlatmate,
       18,
       45,
       {"{P} shares a flat with two friends", "{P} shares a flat with a colleague and takes turns cooking"},
       {"{F} is tired of arguing about the washing-up rota."}},
  };
  return all;
}

const RoleText& role_text(HouseholdRole role) {
  for (const auto& r : role_texts())
    if (r.role == role) return r;
  return role_texts().front();
}

std::string clock_text(int minutes) {
  const int m = ((minutes % 1440) + 1440) % 1440;
  if (m == 0) return "midnight";
  const int h = m / 60, mm = m % 60;
  const int h12 = h % 12 == 0 ? 12 : h % 12;
  std::string s = std::to_string(h12);
  if (mm != 0) s += ":" + std::string(mm < 10 ? "0" : "") + std::to_string(mm);
  return s + (h < 12 ? " am" : " pm");
}

std::string replace_all(std::string s, std::string_view from, std::string_view to) {
  for (std::size_t pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()))
    s.replace(pos, from.size(), to);
  return s;
}

struct Voice {
  std::string first, p, pp, po;
};

std::string capitalised(std::string s) {
  if (!s.empty()) s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
  return s;
}

std::string fill(std::string text, const Voice& v, std::string_view variant = {}) {
  text = replace_all(std::move(text), "{X}", variant);
  text = replace_all(std::move(text), "{F}", v.first);
  text = replace_all(std::move(text), "{P}", capitalised(v.p));
  text = replace_all(std::move(text), "{PP}", capitalised(v.pp));
  text = replace_all(std::move(text), "{pp}", v.pp);
  text = replace_all(std::move(text), "{po}", v.po);
  return replace_all(std::move(text), "{p}", v.p);
}

bool contains_word(const std::string& text, const std::string& phrase) {
  for (std::size_t pos = text.find(phrase); pos != std::string::npos; pos = text.find(phrase, pos + 1)) {
    const bool left = pos == 0 || !std::isalnum(static_cast<unsigned char>(text[pos - 1]));
    const std::size_t end = pos + phrase.size();
    const bool right = end >= text.size() || !std::isalnum(static_cast<unsigned char>(text[end]));
    if (left && right) return true;
  }
  return false;
}

std::set<std::string> content_words(const Persona& p) {
  static const std::set<std::string> stop = {
      "with",  "from",  "that",   "their", "them",     "they", "this",  "when",  "what",  "most",
      "every", "after", "before", "about", "into",     "over", "also",  "works", "goes",  "gets",
      "lives", "still", "often",  "week",  "weekdays", "days", "other", "home",  "where", "whole",
      "long",  "very",  "some",   "than",  "then",     "more", "each"};
  std::set<std::string> names;
  std::string w;
  for (char c : ascii_lower(p.name) + " ") {
    if (std::isalpha(static_cast<unsigned char>(c)))
      w += c;
    else if (!w.empty())
      names.insert(std::exchange(w, {}));
  }
  std::string text = p.occupation + " " + p.routine + " " + p.lifestyle;
  for (const auto& t : p.personality) text += " " + t;
  std::set<std::string> out;
  for (char c : ascii_lower(text) + " ") {
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '-') {
      w += c;
    } else if (!w.empty()) {
      if (w.size() >= 4 && !stop.count(w) && !names.count(w) && w != "she" && w != "her" && w != "his")
        out.insert(w);
      w.clear();
    }
  }
  return out;
}

struct Candidate {
  Persona persona;
  const Occupation* occupation = nullptr;
  int bed = 0, wake = 0;
};

bool reads_back(const Candidate& c) {
  const PersonaTraits t = infer_traits(c.persona);
  WorkPattern expected = c.occupation->pattern;
  if (expected != t.work) return false;
  if (c.occupation->day_sleeper)
    return t.work_night.bed == 8 * 60 && t.work_night.wake == 15 * 60 &&
           t.free_night.bed % 1440 == c.bed % 1440;
  return t.work_night.bed % 1440 == c.bed % 1440 && t.work_night.wake == c.wake;
}

int pick_quarter(Rng& rng, int lo, int hi) {
  const int n = (hi - lo) / 15;
  return lo + 15 * static_cast<int>(rng.between(0, std::max(0, n)));
}

const char* pick_c(Rng& rng, const std::vector<const char*>& v) {
  return v[rng.below(static_cast<std::uint32_t>(v.size()))];
}

std::string routine_text(Rng& rng, const Voice& v, const Occupation& o, int bed, int wake, bool child) {
  if (o.day_sleeper)
    return fill(
        "On work days {F} sleeps from 8 am to 3 pm after {pp} night shift; on free days {p} goes to bed at " +
            clock_text(bed) + " and gets up at " + clock_text(wake) + ".",
        v);
  const std::string b = clock_text(bed), w = clock_text(wake);
  std::vector<std::string> forms = {"{F} goes to bed at " + b + " and gets up at " + w + ".",
                                    "{F} is in bed by " + b + " and up at " + w + ".",
                                    "{F} goes to bed around " + b + " and wakes at " + w + "."};
  if (child)
    forms = {"{F} has to be in bed at " + b + " and gets up at " + w + ".",
             "{F} goes to bed at " + b + " and wakes at " + w + "."};
  return fill(forms[rng.below(static_cast<std::uint32_t>(forms.size()))], v);
}

std::vector<const Occupation*> matching_occupations(const PersonaConstraints& c, HouseholdRole role, int lo,
                                                    int hi) {
  std::vector<const Occupation*> out;
  const std::string wanted = c.occupation ? ascii_lower(*c.occupation) : "";
  for (const auto& o : occupations()) {
    if ((role == HouseholdRole::kChild) != is_child_occupation(o)) continue;
    if (o.pattern == WorkPattern::kHomemaker && role != HouseholdRole::kParent) continue;
    if (std::max(lo, o.min_age) > std::min(hi, o.max_age)) continue;
    if (!wanted.empty()) {
      bool match = contains_word(wanted, o.key) || contains_word(o.key, wanted);
      for (const char* k : o.keywords) match = match || contains_word(wanted, k) || contains_word(k, wanted);
      if (!match) continue;
    }
    out.push_back(&o);
  }
  return out;
}

std::string article_for(const std::string& word) {
  return !word.empty() && std::string("aeiou").find(static_cast<char>(
                              std::tolower(static_cast<unsigned char>(word[0])))) != std::string::npos
             ? "an"
             : "a";
}

}  // namespace

std::string_view household_role_name(HouseholdRole role) {
  switch (role) {
    case HouseholdRole::kSingle:
      return "single";
    case HouseholdRole::kPartner:
      return "partner";
    case HouseholdRole::kParent:
      return "parent";
    case HouseholdRole::kChild:
      return "child";
    case HouseholdRole::kGrandparent:
      return "grandparent";
    case HouseholdRole::kFlatmate:
      return "flatmate";
  }
  return "single";
}

std::optional<HouseholdRole> parse_household_role(std::string_view name) {
  for (auto r : {HouseholdRole::kSingle, HouseholdRole::kPartner, HouseholdRole::kParent,
                 HouseholdRole::kChild, HouseholdRole::kGrandparent, HouseholdRole::kFlatmate})
    if (household_role_name(r) == name) return r;
  return std::nullopt;
}

Result<PersonaRequest> persona_request_from_json(const Json& json, const std::string& pointer) {
  JsonChecker check;
  PersonaRequest r;
  if (!json.is_object()) {
    check.add(pointer, "must be an object");
    return tl::unexpected(check.error("invalid persona request"));
  }
  if (auto v = check.integer(json, pointer, "count", false, 1, 200)) r.count = static_cast<int>(*v);
  if (auto v = check.integer(json, pointer, "seed", false, 0, INT64_MAX))
    r.seed = static_cast<std::uint64_t>(*v);
  const std::string cp = JsonChecker::child(pointer, "constraints");
  if (const Json* c = check.object(json, pointer, "constraints", false)) {
    check.only_keys(*c, cp, {"min_age", "max_age", "occupation", "household_role", "gender"});
    if (auto v = check.integer(*c, cp, "min_age", false, 0, 120))
      r.constraints.min_age = static_cast<int>(*v);
    if (auto v = check.integer(*c, cp, "max_age", false, 0, 120))
      r.constraints.max_age = static_cast<int>(*v);
    if (r.constraints.min_age && r.constraints.max_age && *r.constraints.min_age > *r.constraints.max_age)
      check.add(JsonChecker::child(cp, "max_age"), "must be at least min_age");
    if (auto v = check.string(*c, cp, "occupation", false, 2, 60)) {
      const bool ok = std::all_of(v->begin(), v->end(), [](char ch) {
        return std::isalpha(static_cast<unsigned char>(ch)) || ch == ' ' || ch == '-' || ch == '\'';
      });
      if (!ok)
        check.add(JsonChecker::child(cp, "occupation"),
                  "may contain only letters, spaces, hyphens and apostrophes");
      else
        r.constraints.occupation = *v;
    }
    if (auto v = check.string(*c, cp, "household_role", false, 1, 20)) {
      if (auto role = parse_household_role(*v))
        r.constraints.household_role = role;
      else
        check.add(JsonChecker::child(cp, "household_role"),
                  "must be one of single, partner, parent, child, grandparent, flatmate");
    }
    if (auto v = check.string(*c, cp, "gender", false, 1, 20)) {
      if (*v == "female" || *v == "male")
        r.constraints.gender = *v;
      else
        check.add(JsonChecker::child(cp, "gender"), "must be female or male");
    }
  }
  if (!check.ok()) return tl::unexpected(check.error("invalid persona request"));
  return r;
}

Result<PersonaGenerateRequest> persona_generate_request_from_json(const Json& json) {
  PersonaGenerateRequest r;
  JsonChecker check;
  if (json.is_object()) {
    check.only_keys(json, "", {"count", "seed", "constraints", "generator", "store", "model"});
    if (auto v = check.string(json, "", "generator", false, 1, 20)) {
      if (*v != "offline" && *v != "llm")
        check.add("/generator", "must be offline or llm");
      else
        r.generator = *v;
    }
    r.store = check.boolean(json, "", "store", false).value_or(false);
    r.model = check.string(json, "", "model", false, 1, 200);
    if (r.model && r.generator != "llm") check.add("/model", "a model is chosen only with generator llm");
  }
  auto personas = persona_request_from_json(json);
  std::vector<FieldError> errors = personas ? std::vector<FieldError>{} : personas.error().errors;
  errors.insert(errors.end(), check.errors().begin(), check.errors().end());
  if (!errors.empty())
    return fail(ErrorCode::kValidation, "invalid persona generation request", std::move(errors));
  r.personas = *personas;
  return r;
}

Json to_json(const PersonaConstraints& c) {
  Json j = Json::object();
  if (c.min_age) j["min_age"] = *c.min_age;
  if (c.max_age) j["max_age"] = *c.max_age;
  if (c.occupation) j["occupation"] = *c.occupation;
  if (c.household_role) j["household_role"] = household_role_name(*c.household_role);
  if (c.gender) j["gender"] = *c.gender;
  return j;
}

double persona_similarity(const Persona& a, const Persona& b) {
  const auto wa = content_words(a), wb = content_words(b);
  if (wa.empty() && wb.empty()) return 1.0;
  std::size_t common = 0;
  for (const auto& w : wa) common += wb.count(w);
  return static_cast<double>(common) / static_cast<double>(wa.size() + wb.size() - common);
}

bool near_duplicate(const Persona& a, const Persona& b) {
  if (persona_id(a) == persona_id(b)) return true;
  if (ascii_lower(a.gender) != ascii_lower(b.gender) || std::abs(a.age - b.age) > 5) return false;
  return persona_similarity(a, b) >= 0.5;
}

std::vector<std::string> known_occupations() {
  std::vector<std::string> out;
  for (const auto& o : occupations()) out.emplace_back(o.key);
  return out;
}

Result<std::vector<Persona>> generate_personas_offline(const PersonaRequest& request,
                                                       std::span<const Persona> existing) {
  if (request.count < 1 || request.count > 200)
    return fail(ErrorCode::kValidation, "count must be between 1 and 200",
                {FieldError{"/count", "must be between 1 and 200"}});
  const PersonaConstraints& c = request.constraints;
  const int lo = c.min_age.value_or(0), hi = c.max_age.value_or(120);
  if (lo > hi)
    return fail(ErrorCode::kValidation, "empty age range",
                {FieldError{"/constraints/max_age", "must be at least min_age"}});

  // Roles that fit the age range, and the occupations that fit role and constraints.
  std::vector<HouseholdRole> roles;
  for (const auto& r : role_texts()) {
    if (c.household_role && r.role != *c.household_role) continue;
    if (std::max(lo, r.min_age) > std::min(hi, r.max_age)) continue;
    roles.push_back(r.role);
  }
  std::vector<std::pair<HouseholdRole, std::vector<const Occupation*>>> options;
  for (auto role : roles) {
    const auto& rt = role_text(role);
    auto occ = matching_occupations(c, role, std::max(lo, rt.min_age), std::min(hi, rt.max_age));
    if (!occ.empty()) options.emplace_back(role, std::move(occ));
  }
  // An occupation the list does not know becomes a day job of that name (adults only).
  Occupation custom{"custom",
                    {},
                    WorkPattern::kCommute,
                    18,
                    70,
                    {},
                    "",
                    1350,
                    1410,
                    390,
                    420,
                    false,
                    {"{F} is hoping for a promotion this year.", "{F} is thinking about a change of career."},
                    ""};
  std::string custom_text;
  if (options.empty() && c.occupation && (!c.household_role || *c.household_role != HouseholdRole::kChild) &&
      hi >= 18) {
    custom_text = "{F} works as " + article_for(*c.occupation) + " " + ascii_lower(*c.occupation) +
                  " from 9 am to 5 pm.";
    custom.text = custom_text.c_str();
    custom.min_age = std::max(18, lo);
    custom.max_age = std::min(70, hi);
    for (auto role : roles)
      if (role != HouseholdRole::kChild) {
        const auto& rt = role_text(role);
        if (std::max(custom.min_age, rt.min_age) <= std::min(custom.max_age, rt.max_age))
          options.push_back({role, {&custom}});
      }
  }
  if (options.empty()) {
    std::string known;
    for (const auto& k : known_occupations()) known += (known.empty() ? "" : ", ") + k;
    return fail(ErrorCode::kValidation, "no persona fits these constraints",
                {FieldError{c.occupation ? "/constraints/occupation" : "/constraints",
                            "no occupation fits the age range and household role (known: " + known + ")"}});
  }

  Rng rng(request.seed, fnv1a64("personas"));
  std::vector<Persona> out;
  std::vector<Persona> taken(existing.begin(), existing.end());
  const int max_attempts = 60 * request.count + 200;
  for (int attempt = 0; attempt < max_attempts && static_cast<int>(out.size()) < request.count; ++attempt) {
    const auto& [role, occs] = options[rng.below(static_cast<std::uint32_t>(options.size()))];
    const Occupation& o = *occs[rng.below(static_cast<std::uint32_t>(occs.size()))];
    const RoleText& rt = role_text(role);
    const int age_lo = std::max({lo, rt.min_age, o.min_age}), age_hi = std::min({hi, rt.max_age, o.max_age});
    if (age_lo > age_hi) continue;
    Candidate cand;
    cand.occupation = &o;
    Persona& p = cand.persona;
    p.age = static_cast<int>(rng.between(age_lo, age_hi));
    const bool female = c.gender ? *c.gender == "female" : rng.chance(0.5);
    p.gender = female ? "female" : "male";
    const Culture& culture = cultures()[rng.below(static_cast<std::uint32_t>(cultures().size()))];
    const std::string first = pick_c(rng, female ? culture.female : culture.male);
    p.name = first + " " + pick_c(rng, culture.surnames);
    const Voice v{first, female ? "she" : "he", female ? "her" : "his", female ? "her" : "him"};

    cand.bed = pick_quarter(rng, o.bed_lo, o.bed_hi);
    cand.wake = pick_quarter(rng, o.wake_lo, o.wake_hi);
    const bool child = role == HouseholdRole::kChild;
    p.routine = routine_text(rng, v, o, cand.bed, cand.wake, child);
    std::string variant = o.variants.empty() ? "" : pick_c(rng, o.variants);
    variant = fill(variant, v);
    p.occupation = fill(o.text, v, variant);

    // Personality: a tidiness lean, a sociability lean, and one or two other traits.
    std::vector<std::string> traits;
    const double t_roll = rng.uniform(), s_roll = rng.uniform();
    if (t_roll < 0.4)
      traits.emplace_back(pick_c(rng, kTidyTraits));
    else if (t_roll < 0.75)
      traits.emplace_back(pick_c(rng, kMessyTraits));
    if (s_roll < 0.4)
      traits.emplace_back(pick_c(rng, kSocialTraits));
    else if (s_roll < 0.75)
      traits.emplace_back(pick_c(rng, kSolitaryTraits));
    while (traits.size() < 3 || (traits.size() < 4 && rng.chance(0.3))) {
      std::string t = pick_c(rng, kOtherTraits);
      if (std::find(traits.begin(), traits.end(), t) == traits.end()) traits.push_back(std::move(t));
    }
    p.personality = traits;

    // Lifestyle: household, two or three hobbies, a work habit, a tidiness habit.
    std::vector<const Hobby*> fit;
    for (const auto& h : hobbies())
      if (p.age >= h.min_age && p.age <= h.max_age) fit.push_back(&h);
    rng.shuffle(fit);
    const std::size_t n_hobbies = std::min<std::size_t>(fit.size(), rng.chance(0.5) ? 2 : 3);
    std::string life = fill(pick_c(rng, rt.lines), v) + ". " + capitalised(v.p) + " ";
    for (std::size_t i = 0; i < n_hobbies; ++i)
      life += fill(fit[i]->text, v) + (i + 2 < n_hobbies ? ", " : i + 2 == n_hobbies ? " and " : ".");
    if (*o.habit) life += " " + fill(o.habit, v) + ".";
    const bool tidy = std::any_of(traits.begin(), traits.end(), [](const std::string& t) {
      return std::find_if(kTidyTraits.begin(), kTidyTraits.end(), [&](const char* x) { return t == x; }) !=
             kTidyTraits.end();
    });
    const bool messy = std::any_of(traits.begin(), traits.end(), [](const std::string& t) {
      return std::find_if(kMessyTraits.begin(), kMessyTraits.end(), [&](const char* x) { return t == x; }) !=
             kMessyTraits.end();
    });
    if (tidy && !child) life += " " + capitalised(v.p) + " " + fill(pick_c(rng, kTidyHabits), v) + ".";
    if (messy && !child) life += " " + capitalised(v.p) + " " + fill(pick_c(rng, kMessyHabits), v) + ".";
    p.lifestyle = life;

    std::vector<const char*> thoughts = o.thoughts;
    thoughts.insert(thoughts.end(), rt.thoughts.begin(), rt.thoughts.end());
    p.thoughts = fill(pick_c(rng, thoughts), v);

    if (!persona_from_json(to_json(p))) continue;
    if (!reads_back(cand)) continue;
    const bool dup =
        std::any_of(taken.begin(), taken.end(), [&](const Persona& q) { return near_duplicate(p, q); });
    if (dup) continue;
    taken.push_back(p);
    out.push_back(std::move(p));
  }
  if (static_cast<int>(out.size()) < request.count)
    return fail(ErrorCode::kValidation,
                "only " + std::to_string(out.size()) +
                    " distinct personas fit these constraints; ask for fewer or widen them",
                {FieldError{"/count", "at most " + std::to_string(out.size()) + " with these constraints"}});
  return out;
}

}  // namespace socsim::household
