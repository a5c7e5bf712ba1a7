// Placeholder so the stats library exists until its sources land (issue 5).
