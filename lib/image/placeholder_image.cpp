// Placeholder so the image library exists until its sources land (issue 5).
